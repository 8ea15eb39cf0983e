// How `generate` packs N rooms onto the play area so that their summed floor
// (the expansion ratio) is as large as the overlap limit allows.
//
// The issue's own example shows the idea: on a 4 x 4 m floor, strips of
// 1.6 x 4 m, three along x and three along z, cross each other by 2.56 m²
// (40 % of a strip) and lie beside their parallel neighbours. The search
// tries such lattices: in frames turned to the play area's own edge
// directions (and to a seeded angle for variety), n1 strips along one axis
// and N - n1 along the other, each as long as the play area allows within
// its band, widths scanned from 1.5 m in 5 cm steps. A lattice is kept when
// every room is inside the play area and at least 1.5 m wide, every pair
// overlaps by at most the limit (design/overlap.hpp, or --max-overlap), and
// doors can join all the rooms (pack_doors.hpp). The seed picks one of the
// lattices within 2 % of the best, mirrors it, and then drives a local search
// that grows, moves and bends rooms (an arm that makes a rectangle an L, a
// turn) and keeps any move that keeps every rule and does not lose floor; a
// corridor (an annular sector) may replace a room where it adds floor.
//
// Deterministic: splitmix64 and work budgets counted in tries, not seconds.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "design/pack_shape.hpp"

namespace impossible::design {

struct PackRules {
    math::Polygon2 area;  // simple, at most kPackMaxCorners corners
    int rooms = 1;
    std::uint64_t seed = 1;
    std::optional<double> max_overlap;  // percent; none: Suma et al.'s limits
};

inline constexpr std::size_t kPackMaxCorners = 64;

// A door pair: `from`'s door in its wall `wall`, facing into `from`; `to`'s
// door at the same place facing the other way (the transfer is the identity).
struct PackedDoor {
    int from = -1, to = -1;
    glm::dvec2 centre{0.0};
    glm::dvec2 normal{0.0};  // unit, into `from`
};

struct Packing {
    std::vector<Shape> shapes;  // in the order the rooms are written (and walked)
    std::vector<RoomGeom> rooms;
    std::vector<PackedDoor> doors;
    double floor_area = 0.0;  // m², summed over rooms
};

// Whether two rooms may share the floor they share.
bool pair_allowed(const RoomGeom& a, const RoomGeom& b, const std::optional<double>& max_overlap);

// The best packing found, or nothing.
std::optional<Packing> pack_rooms(const PackRules& rules);

// In pack_doors.cpp: orders the rooms as a chain (each joined to the next
// by a door) where the doors allow one, else as a tree walked depth first,
// and places the doors; nothing when they cannot all be placed.
std::optional<Packing> join_rooms(std::vector<Shape> shapes, std::vector<RoomGeom> rooms, std::uint64_t seed);

}  // namespace impossible::design
