// `impossible walk LAYOUT --path FILE` (cli.md): replays a walk.
//
// The path file holds one frame a line: the physical head pose,
// `X Y Z YAW PITCH ROLL` (metres, degrees), optionally followed by the left
// and the right hand's (18 numbers), separated by spaces or tabs
// (layout/path_file.hpp). Blank lines and lines whose first non-blank
// character is `#` are skipped; a trailing '\r' is ignored. Every number is
// finite, positions within ±1e6 m and angles within ±1e6°.
//
// The whole file is read and checked before anything is printed: a bad line
// gives one line `FILE:LINE: message` on err, nothing on out, and status 1.
//
// Output: one JSON object a line per pose, frame numbered from 0:
//   {"frame":0,"room":"hall","teleports":[],"position":[0,1.6,1],"forward":[0,0,-1]}
// then, on a line with hands, "hands":["ROOM","ROOM"] (left, right: the room
// each hand is in, walked from the head centre after the frame's teleports
// to the hand's virtual position, walk::place_hand), and, when the layout has
// moving props, on every line "props":{"ID":"ROOM",...}: each prop with a
// motion, in layout order, and its room at time frame / fps
// (walk::walk_prop, through one walk::PropWalks for the whole path), and,
// last, on the line of a frame at which changes are made,
// "changes":["ID",...] (layout-format.md, "Changes while walking").
// Numbers are written by impossible::format_number (base/format.hpp): the
// shortest decimal that reads back to the same double, integers without a
// fraction ("1", not "1.0"), 1.6 as "1.6", 6.1e-17 as "6.1e-17"; -0 as 0.
#pragma once

#include <istream>
#include <ostream>
#include <string>

#include "layout/layout.hpp"
#include "layout/path_file.hpp"
#include "session/session.hpp"

namespace impossible::app {

// Reads the path file and replays it. Returns 0, or 1 on a bad or unreadable
// path file (one line on err).
struct WalkSettings {
    // Line k is at time k / fps (> 0, finite).
    double fps = layout::kDefaultPathFps;
    // The view options that place the eyes of the seen test (a layout with
    // changes; layout-format.md, "Changes while walking").
    math::View view;
    // --stats: one line on err after the walk, "stats: frames=N
    // seen_tests=K seen_passes_max=P seen_us_median=X seen_us_max=Y"
    // (microseconds on a monotonic clock, of the frames that ran it).
    bool stats = false;
};
int run_walk(const session::Session& session, const std::string& path_file, std::ostream& out, std::ostream& err,
             const WalkSettings& settings = {});

// The same on an already open stream; `name` is the FILE of error messages.
int run_walk_stream(const session::Session& session, std::istream& in, const std::string& name, std::ostream& out,
                    std::ostream& err, const WalkSettings& settings = {});

}  // namespace impossible::app
