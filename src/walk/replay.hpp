// Replaying a path file's frames (cli.md, "Time, hands and lights"): what
// `render --path`, `trace --path`, `preview --path` and `bench --path` draw
// for a line. The head is the walker's virtual head after the line's step;
// the hands are the line's physical hand poses mapped by the walker's W
// (position and orientation), so a hand moves with the head through every
// door the head has passed; the time is line / fps.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "layout/layout.hpp"
#include "layout/path_file.hpp"
#include "math/pose.hpp"
#include "math/view.hpp"
#include "walk/walker.hpp"

namespace impossible::walk {

using HandPoses = std::optional<std::array<math::HeadPose, 2>>;

// A physical pose mapped by the rigid W: position W · p, rotation W's times
// the pose's, as yaw, pitch and roll (math::head_pose_from).
math::HeadPose virtual_pose(const math::dmat4& physical_to_virtual, const math::HeadPose& physical);

// Both hands mapped by W; none stays none.
HandPoses virtual_hands(const math::dmat4& physical_to_virtual, const HandPoses& physical);

// The view's head, room and hands after the walker's last step, whose line
// held `physical_hands`; every other field of `view` is kept.
void set_walked_view(math::View& view, const Walker& walker, const HandPoses& physical_hands);

// The time of line `line` at `fps` frames a second.
inline double line_time(std::size_t line, double fps) { return static_cast<double>(line) / fps; }

// Walks lines 0..line of `frames` with a new `walker` (as `walk` does)
// and sets the view's head, room and hands to line `line`'s and its time to
// line / fps. `line` must be below frames.size().
void replay_view(math::View& view, Walker& walker, const std::vector<layout::PathFrame>& frames, std::size_t line,
                 double fps);

// The same with a walker from the layout's start that links the layout
// itself (tests and tools; the program replays through session::Session).
void set_replayed_view(math::View& view, const layout::Layout& layout, const std::vector<layout::PathFrame>& frames,
                       std::size_t line, double fps);

}  // namespace impossible::walk
