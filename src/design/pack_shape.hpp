// The rooms `generate` packs onto the play area, and the geometry it asks of
// them: a rectangle turned at any angle, an L (a rectangle with an arm at
// one corner of one side) or a curved corridor (an annular sector whose arcs
// are chains of short walls, as in Vasylevska et al.'s Flexible Spaces).
//
// Every room's floor is an outline (counter-clockwise, corners rounded to
// millimetres: what the layout file will hold) and the convex pieces that
// tile it (a rectangle: itself; an L: its body and its arm; a corridor: one
// quadrilateral per wall of its outer arc), so that the floor two rooms
// share is the sum over pairs of pieces of convex clipping. Units metres;
// floor points are (x, z).
#pragma once

#include <optional>
#include <vector>

#include "math/polygon.hpp"

namespace impossible::design {

inline constexpr double kRoomMinWidth = 1.5;     // m; every room at least this wide
inline constexpr double kPackDoorWidth = 0.9;    // m
inline constexpr double kDoorReach = 0.8;        // m of the next room beyond a door
inline constexpr double kDoorPassage = 0.6;      // m left free beside a door standing in a room
inline constexpr double kArcWallDegrees = 12.0;  // a corridor's walls turn by at most this much
inline constexpr double kMaxRoomSpan = 12.0;     // m: no room reaches further along x or z

struct Shape {
    enum class Kind { Rect, L, Arc };
    Kind kind = Kind::Rect;
    // Rect and L: the body [u0, u1] x [v0, v1] in a frame turned by `angle`
    // (radians): a point is U * (cos, sin) + V * (-sin, cos).
    double angle = 0.0;
    double u0 = 0.0, u1 = 0.0, v0 = 0.0, v1 = 0.0;
    // L: the arm beyond side `arm_side` (0 +V, 1 -V, 2 +U, 3 -U), flush with
    // that side's high end (arm_high) or low end, arm_width along the side,
    // arm_length out of it.
    int arm_side = 0;
    bool arm_high = false;
    double arm_width = 0.0, arm_length = 0.0;
    // Arc: radii r0 < r1 about `centre`, from angle a0 to a1 (radians, a0 < a1).
    glm::dvec2 centre{0.0};
    double r0 = 0.0, r1 = 0.0, a0 = 0.0, a1 = 0.0;
};

struct RoomGeom {
    math::Polygon2 outline;              // counter-clockwise, millimetres
    std::vector<math::Polygon2> pieces;  // convex, tiling the outline
    double area = 0.0;
    glm::dvec2 lo{0.0}, hi{0.0};  // bounding rectangle
    bool box = false;             // an axis-aligned rectangle (a box room)
};

RoomGeom room_geom(const Shape& shape);

// The narrowest the room is: a rectangle's shorter side, the narrower of an
// L's body and arm, a corridor's width at the middle of its outer walls.
double shape_width(const Shape& shape);

// Floor two rooms share, m².
double shared_area(const RoomGeom& a, const RoomGeom& b);

// Whether the room lies inside the play area (at most 1e-9 m² outside).
bool inside_area(const RoomGeom& room, const math::Polygon2& area);

// Where the line p + t d (d unit) runs inside the outline: sorted disjoint
// intervals of t.
struct Interval {
    double lo = 0.0, hi = 0.0;
};
std::vector<Interval> line_inside(const math::Polygon2& outline, glm::dvec2 p, glm::dvec2 d);

// A door in wall `wall` of room `from` (outline edge wall -> wall + 1)
// leading into room `to`: the stretches of that wall where the door's
// centre may go, as intervals of the distance from the wall's first corner.
// The door is kPackDoorWidth wide, at least 0.1 m from the wall's ends, with
// `from` in front of it and `to` behind it for kDoorReach; in `to` (where it
// stands free) it leaves kDoorPassage free on one side and keeps 0.05 m
// from `to`'s walls on the other.
std::vector<Interval> door_stretches(const RoomGeom& from, int wall, const RoomGeom& to);

// Whether some wall of `from` can hold a door into `to`.
bool door_possible(const RoomGeom& from, const RoomGeom& to);

}  // namespace impossible::design
