// `impossible generate`: a random, valid layout of N rooms on a given floor,
// in the spirit of Vasylevska and Kaufmann's procedural "Flexible Spaces"
// (Vasylevska, Kaufmann, Bolas and Suma, IEEE 3DUI 2013; here rooms are
// boxes and doors are portals, not corridors).
//
// Rooms are axis-aligned boxes on a 0.1 m grid, each inside the play area.
// The first room is placed at random; each further room B grows out of a
// wall of an existing room A: a door in A's wall, and a coincident door in B
// facing the other way (so the transfer is the identity and B lies where it
// is drawn on the physical floor). B reaches at least kMinReach beyond A's
// wall, so there is room to step through, and may reach back into A: that
// part is the overlap, the impossible part. B's door stands free in B, or
// lies in B's wall when B only touches A. Every pair of rooms must overlap
// by at most the limit (a percentage of the smaller floor: --max-overlap, or
// by default the published threshold of design/overlap.hpp). Each room gets
// its own hue, a checker on every other room, and one or two props of its
// own shape in corners away from its doors.
//
// Deterministic: a splitmix64 generator and integer decimetres throughout;
// the same options write the same bytes.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "base/result.hpp"
#include "math/polygon.hpp"

namespace impossible::design {

inline constexpr int kMinRoomSide = 15;  // dm
inline constexpr int kMaxRoomSide = 50;  // dm
inline constexpr int kMinReach = 8;      // dm that a new room reaches beyond its parent's wall
inline constexpr int kDoorWidth = 9;     // dm
inline constexpr int kDoorSideRoom = 8;  // dm beside a free-standing door
inline constexpr int kMaxGeneratedRooms = 64;

struct GenerateOptions {
    math::Polygon2 play_area;  // metres (x, z), simple
    bool rectangle = false;    // write play_area as min/max (a W x D floor)
    int rooms = 4;
    std::uint64_t seed = 1;
    std::optional<double> max_overlap;  // percent of the smaller floor
};

// The layout as JSON text (ends with a newline), or why it could not be made.
Result<std::string> generate_layout(const GenerateOptions& options);

}  // namespace impossible::design
