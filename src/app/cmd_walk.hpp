// `impossible walk LAYOUT --path FILE` (cli.md): replays a walk.
//
// The path file holds one physical head pose a line, `X Y Z YAW PITCH ROLL`
// (metres, degrees), separated by spaces or tabs. Blank lines and lines whose
// first non-blank character is `#` are skipped; a trailing '\r' is ignored.
// Every other line must hold exactly six finite numbers, positions within
// ±1e6 m and angles within ±1e6°.
//
// The whole file is read and checked before anything is printed: a bad line
// gives one line `FILE:LINE: message` on err, nothing on out, and status 1.
//
// Output: one JSON object a line per pose, frame numbered from 0:
//   {"frame":0,"room":"hall","teleports":[],"position":[0,1.6,1],"forward":[0,0,-1]}
// Numbers are written by impossible::format_number (base/format.hpp): the
// shortest decimal that reads back to the same double, integers without a
// fraction ("1", not "1.0"), 1.6 as "1.6", 6.1e-17 as "6.1e-17"; -0 as 0.
#pragma once

#include <istream>
#include <ostream>
#include <string>

#include "layout/layout.hpp"

namespace impossible::app {

// Reads the path file and replays it. Returns 0, or 1 on a bad or unreadable
// path file (one line on err).
int run_walk(const layout::Layout& layout, const std::string& path_file, std::ostream& out, std::ostream& err);

// The same on an already open stream; `name` is the FILE of error messages.
int run_walk_stream(const layout::Layout& layout, std::istream& in, const std::string& name, std::ostream& out,
                    std::ostream& err);

}  // namespace impossible::app
