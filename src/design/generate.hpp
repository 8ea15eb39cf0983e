// `impossible generate`: a random, valid layout of N rooms on a given floor,
// in the spirit of Vasylevska and Kaufmann's procedural "Flexible Spaces"
// (Vasylevska, Kaufmann, Bolas and Suma, IEEE 3DUI 2013).
//
// The rooms are packed onto the play area so that their summed floor, the
// expansion ratio, is as large as the overlap limit allows
// (design/pack_search.hpp): strips turned to the play area's edges that
// cross their neighbours, bent into L-shapes, turned, or made curved
// corridors where that adds floor; each room inside the play area and at
// least 1.5 m wide, every pair overlapping by at most the limit (a
// percentage of the smaller floor: --max-overlap, or by default the
// published threshold of design/overlap.hpp). Consecutive rooms are joined by
// coincident doors (the transfer is the identity, so a room lies where it is
// drawn on the physical floor): a door in a wall of one room, standing free
// in the other (or in its wall where the two only touch), with room to walk
// past it. Where the packer finds nothing (a play area of more than
// kPackMaxCorners corners, or rooms that do not fit its lattices), rooms are
// grown out of each other as boxes on a 0.1 m grid (generate_boxes.cpp), the
// first placed at random or, where none fits so, on the play area's widest
// spot (widest_spot.hpp), which the messages name when the rooms do not fit.
// Each room gets its own hue, a checker on every other room, and one or two
// props of its own shape in corners away from its doors.
//
// Deterministic: a splitmix64 generator and work budgets counted in tries;
// the same options write the same bytes.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "base/result.hpp"
#include "design/widest_spot.hpp"
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

struct Generated {
    std::string text;  // the layout as JSON (ends with a newline)
    int rooms = 0;
    double floor_area = 0.0;  // m², summed over rooms
    double play_area = 0.0;   // m²
    double expansion_ratio = 0.0;
};

// The layout, or why it could not be made (one line).
Result<Generated> generate(const GenerateOptions& options);

// The layout as JSON text (ends with a newline), or why it could not be made.
Result<std::string> generate_layout(const GenerateOptions& options);

struct Packing;
// In generate_boxes.cpp: rooms grown out of each other as boxes, up to 200
// restarts, and no restart once the boxes' tests against a play area of
// many corners have tested kMaxBoxWork edges (AreaIndex::edges_tested): a
// 10,000-corner star roomy only in its 4 m core tests about 10^7 edges a
// restart, and took 23 s for 200. `spot` is the play area's widest spot,
// found here when it is needed and not given (a search of up to 0.5 s, done
// once for all the calls of one generate).
inline constexpr std::uint64_t kMaxBoxWork = 200'000'000;
std::optional<Packing> grow_boxes(const GenerateOptions& options, std::optional<WidestSpot>& spot);

}  // namespace impossible::design
