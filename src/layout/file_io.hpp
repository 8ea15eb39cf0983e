// Reading whole files with a size limit and clear reasons for failure.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "base/result.hpp"

namespace impossible::layout::detail {

// Reads the file at `path` (at most `max_bytes`). On failure the error is a
// short reason that follows the file's name ("does not
// exist", "is a directory", "is too large (...)", "cannot be opened:
// Permission denied").
// `regular_only` refuses devices and pipes (which could block or never end).
Result<std::vector<unsigned char>> read_file_bytes(const std::string& path, std::size_t max_bytes,
                                                  bool regular_only);

// The same checks without reading (size, kind), for a clear message before
// handing the path to a library.
Result<void> check_readable_file(const std::string& path, std::size_t max_bytes, bool regular_only);

}  // namespace impossible::layout::detail
