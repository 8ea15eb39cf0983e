// The path file of `walk`, `preview --path` and `bench --path`: physical head
// poses, one a line: `X Y Z YAW PITCH ROLL`, blank lines and
// `#` comments skipped, six finite numbers a line, positions within ±1e6 m and
// angles within ±1e6°.
#pragma once

#include <cstddef>
#include <istream>
#include <string>
#include <vector>

#include "base/result.hpp"
#include "math/pose.hpp"

namespace impossible::layout {

// The poses, or an error "FILE:LINE: message" or "FILE: message".
using PathFile = Result<std::vector<math::HeadPose>>;

// Path files are at most this long (like layouts: 4 MiB, about 100,000 poses).
inline constexpr std::size_t kMaxPathFileBytes = 4u << 20;

// Reads a file for a replay: at least one pose is required. Errors are one
// line: "FILE: does not exist", "FILE: is too large (...)", "FILE:LINE: ...".
PathFile read_path_file(const std::string& path);
// Reads a stream; no poses is not an error here (`walk` then prints nothing).
PathFile read_path_stream(std::istream& in, const std::string& name);

}  // namespace impossible::layout
