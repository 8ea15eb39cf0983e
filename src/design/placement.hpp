// Where each room lies on the physical floor, and which rooms a walker can
// reach from the start through doors.
//
// A walk starts in `start.room` with W = identity (physical = virtual). Going
// through door A into B's room makes W ← M_AB · W (scene/walk.hpp), so room
// B's own coordinates map onto the physical floor by (M_AB · W)⁻¹. Rooms are
// found breadth first from the start, each door of a room in file order, and
// each room is placed by the first (fewest doors) way found. A layout whose
// doors turn or move space (loop.json) can reach a room in several places;
// `inconsistent` marks those, and the first place is the one reported.
// Rooms no door leads to keep their own coordinates. Mirrors and windows are
// not walked through: a room seen only through a window is not reachable.
//
// Floor points are (x, z) in metres (math/polygon.hpp).
#pragma once

#include <array>
#include <vector>

#include "layout/layout.hpp"
#include "math/polygon.hpp"
#include "walk/walker.hpp"

namespace impossible::design {

struct RoomPlacement {
    bool reachable = false;
    bool inconsistent = false;     // reached elsewhere on the floor by another way
    math::dmat4 to_physical{1.0};  // the room's coordinates → physical
    int parent = -1;               // the room it is entered from; -1 for the start
    int via = -1;                  // the door (of `parent`) walked through
    int doors = 0;                 // doors passed from the start
};

struct Placement {
    links::PortalLinks links;
    std::vector<RoomPlacement> rooms;  // one per layout room
    std::vector<int> order;            // reachable rooms, breadth first from the start
};

Placement place_rooms(const layout::Layout& layout);

// A room's floor mapped to the physical floor: a box room's rectangle (4
// corners), a prism room's polygon (layout::floor_outline, counter-
// clockwise; a rigid placement keeps it so).
math::Polygon2 physical_floor(const layout::Room& room, const math::dmat4& to_physical);

// The floor line of a door's rectangle (its bottom edge dropped to y = 0),
// mapped to the physical floor: the two ends.
std::array<glm::dvec2, 2> door_line(const layout::Portal& portal, const math::dmat4& to_physical);

// A point of a room's coordinates on the physical floor.
glm::dvec2 to_floor(const math::dmat4& to_physical, const math::dvec3& p);

}  // namespace impossible::design
