// A large, regular layout for measuring how loading, validation and rendering
// scale with the number of rooms (bench/large-layouts.sh, docs in bench/README.md).
//
// N rooms of 4 x 4 x 3 m on a grid, joined in one chain that snakes through
// rows of kLargeRowLength rooms: along -z in even rows, back along +z in odd
// rows, and across a +x wall from the end of one row to the next. Every door
// pair is coincident (identity transfer), a hole 0.9 x 2.1 m in the shared
// wall. Doors along a row alternate between 1.2 m and 2.8 m from the row's -x
// wall, so no straight line passes three doors in a row: the start room
// (room 0, head at its +z end looking along -z) sees rooms 0, 1 and 2 only,
// whatever N is. Each room has three box props away from its doors and a
// hue of its own. The play area covers the whole grid.
//
// Deterministic: the same N writes the same bytes.
#pragma once

#include <string>

namespace impossible::design {

inline constexpr int kLargeRowLength = 10;
inline constexpr int kMaxLargeRooms = 100000;

// The layout as JSON text (ends with a newline); rooms in 1..kMaxLargeRooms.
// It has `rooms` rooms and 2 * (rooms - 1) portals.
std::string large_layout_text(int rooms);

}  // namespace impossible::design
