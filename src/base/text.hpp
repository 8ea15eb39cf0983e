// Text that goes into one-line messages: a path or a name from the user may
// hold a newline, control characters or megabytes.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace impossible {

// `text` on one line: newline, tab and carriage return as \n, \t, \r, other
// control bytes as \xNN; longer than `max_bytes`, it is cut (at a character
// boundary) and ends in "... (N more bytes)".
std::string one_line(std::string_view text, std::size_t max_bytes = 2000);

}  // namespace impossible
