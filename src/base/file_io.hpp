// Reading whole input files with a size limit, clear reasons for failure and
// no hanging: every input of the program (layouts, path files, glTF models,
// PNGs to compare) is read through here.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "base/result.hpp"

namespace impossible {

// How long a pipe, FIFO or terminal may stay silent before reading it fails
// (a FIFO nobody writes to would otherwise block forever). The environment
// variable IMPOSSIBLE_INPUT_TIMEOUT_MS overrides it (tests use a short one).
inline constexpr int kInputIdleTimeoutMs = 10'000;

// Reads the file at `path` (at most `max_bytes`). On failure the error is a
// short reason that follows the file's name ("does not exist", "is a
// directory", "is too large (...)", "cannot be opened: Permission denied",
// "sent no data for 10 s"). Files that are not regular (pipes, FIFOs,
// devices such as /dev/zero) are read without blocking, up to the same limit,
// and fail after kInputIdleTimeoutMs without data.
// `regular_only` refuses them instead.
Result<std::vector<unsigned char>> read_file_bytes(const std::string& path, std::size_t max_bytes, bool regular_only);

// The same checks without reading (size, kind), for a clear message before
// handing the path to a library.
Result<void> check_readable_file(const std::string& path, std::size_t max_bytes, bool regular_only);

// A size for messages: "5 MiB" when a whole number of MiB, else "123 bytes".
std::string format_bytes(std::uint64_t bytes);

}  // namespace impossible
