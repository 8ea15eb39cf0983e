// A file read for a layout (the layout's textures, glTF models and their
// buffers and images), so that a command can refuse an output that would
// overwrite one of them (cli/output_files.hpp).
#pragma once

#include <string>

namespace impossible::assets {

struct FileRead {
    std::string what;  // "the texture", "the glTF model", "a file of the glTF model M:"
    std::string path;  // as it was opened
};

}  // namespace impossible::assets
