// What stands in a walker's way: the props that reach below the head, as
// floor rectangles in each room's own coordinates, and the doors whose way
// through one of them blocks (issue 38: a prop across a doorway, a moving
// crate parked past a door). `tour` plans round the same obstacles
// (design/room_grid.hpp), so the doors `validate` names as blocked are the
// ones `tour` cannot take.
//
// A prop without a motion stands where it is listed. A moving prop
// (layout-format.md, "Moving props") stands where its motion puts it at
// time 0 and, when the motion does not loop, also where it comes to rest
// (its last key), in the room its anchor walks to there: a looping prop
// comes back, a parked one stays. A model counts by the bounding box of its
// placed triangles; a turned moving prop by the bounding rectangle of its
// turned box.
#pragma once

#include <string>
#include <vector>

#include "layout/layout.hpp"
#include "links/portal_links.hpp"
#include "math/conventions.hpp"

namespace impossible::design {

struct Obstacle {
    glm::dvec2 lo{0.0}, hi{0.0};  // the floor rectangle (x, z) in the room's coordinates
    int listed_room = -1;         // the room the prop is listed in
    int prop = -1;                // its index among that room's props
    bool resting = false;         // a moving prop where its motion leaves it
};

// Distance from p to the obstacle's rectangle (0 inside).
double obstacle_distance(const glm::dvec2& p, const Obstacle& o);

// Per room, its obstacles: props whose lowest point is at most
// head_height + 0.2 m (a prop wholly above that is passed under).
std::vector<std::vector<Obstacle>> room_obstacles(const layout::Layout& layout, const links::PortalLinks& links,
                                                  double head_height);

// One room's props where they are listed, moving ones too (no motion walked).
std::vector<Obstacle> listed_obstacles(const layout::Layout& layout, int room, double head_height);

// "rooms[0].props[2] (table)": the prop by its place in the file, and by its
// id where it has one; "... where its motion leaves it" for a resting one.
std::string obstacle_name(const layout::Layout& layout, const Obstacle& o);

// A door's way through: the body (radius `body_radius`) walking straight
// from `clearance` in front of the door to its centre, as `tour` crosses
// it. A prop in the door's room that reaches into that band blocks the
// door; a prop behind its partner (in front of the partner, in the target
// room) blocks the partner, and so the way back.
struct BlockedDoor {
    int portal = -1;  // the door whose front is blocked
    Obstacle by;      // the first obstacle found there, in the room's order
};

// Every paired door whose front is blocked, in portal order.
std::vector<BlockedDoor> blocked_doors(const layout::Layout& layout,
                                       const std::vector<std::vector<Obstacle>>& obstacles, double body_radius = 0.25,
                                       double clearance = 0.35);

// The blocked door on the way from the start to `room` (the doors that
// placed it, design/placement.hpp, each way), or nullptr.
struct Placement;
const BlockedDoor* blocked_on_way(const layout::Layout& layout, const Placement& placement,
                                  const std::vector<BlockedDoor>& blocked, int room);

}  // namespace impossible::design
