// The path file of `walk`, `preview --path` and `bench --path`: physical
// poses, one line a frame: `X Y Z YAW PITCH ROLL` (the head) or 18 numbers
// (the head, then the left and the right hand, each X Y Z YAW PITCH ROLL); one
// file may mix them. Blank lines and `#` comments are skipped, a number may
// start with one sign (`+-1` is refused), every number is finite, positions
// within ±1e6 m and angles within ±1e6°.
#pragma once

#include <array>
#include <cstddef>
#include <istream>
#include <optional>
#include <string>
#include <vector>

#include "base/result.hpp"
#include "math/pose.hpp"

namespace impossible::layout {

// The poses, or an error "FILE:LINE: message" or "FILE: message".
using PathFile = Result<std::vector<math::HeadPose>>;

// One line of a path file (cli.md, "Time, hands and lights"): 6 numbers, the
// head; or 18, the head, then the left and the right hand (physical poses).
struct PathFrame {
    math::HeadPose head;
    std::optional<std::array<math::HeadPose, 2>> hands;  // none on a 6-number line
};
using PathFrames = Result<std::vector<PathFrame>>;

// The default frame rate of a replay (--fps): line k is at time k / fps.
inline constexpr double kDefaultPathFps = 90.0;

// Path files are at most this long (like layouts: 4 MiB, about 100,000 poses).
inline constexpr std::size_t kMaxPathFileBytes = 4u << 20;

// Reads a file for a replay. Errors are one line: "FILE: does not exist",
// "FILE: is too large (...)", "FILE:LINE: ...". A file with no poses is an
// error for every command ("FILE: the path file holds no poses"); a UTF-8 byte
// order mark is skipped, UTF-16 and UTF-32 are refused by name.
PathFile read_path_file(const std::string& path);
// The same for a stream already open (`walk`), with `name` in the messages.
PathFile read_path_stream(std::istream& in, const std::string& name);
// Every line with its hands, for the commands that replay hands; the two
// readers above keep the heads only.
PathFrames read_path_frames_file(const std::string& path);
PathFrames read_path_frames_stream(std::istream& in, const std::string& name);

}  // namespace impossible::layout
