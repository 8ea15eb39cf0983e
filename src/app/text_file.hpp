// Text outputs written whole or not at all (like png_io.hpp's PNGs): under a
// temporary name in the same directory, then renamed.
#pragma once

#include <string>

namespace impossible::app {

// Returns an error message naming the file, or "".
std::string write_text_file(const std::string& path, const std::string& text);

}  // namespace impossible::app
