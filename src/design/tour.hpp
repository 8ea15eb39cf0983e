// A walk that visits every room a door leads to, planned for `impossible
// tour`. The rooms are taken depth first along the doors that placed them
// (design/placement.hpp), so the walker's W in each room is the room's
// placement: walk to the door (design/room_grid.hpp), straight through it
// (ducking to fit a low door), to the free point nearest the room's centre,
// on to its further doors, and back out the way it came. Every pose is a
// physical head pose at head height, a step apart; the head faces where it
// goes. The result is then replayed with the project's walker
// (scene/walk.hpp): the rooms, teleports and distances reported are the
// walker's, not the planner's.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "base/result.hpp"
#include "design/room_grid.hpp"
#include "layout/layout.hpp"
#include "links/portal_links.hpp"
#include "math/pose.hpp"

namespace impossible::design {

struct TourOptions {
    GridOptions grid;
    double step = 0.05;            // m between poses at most
    double door_clearance = 0.35;  // m in front of and behind a door where the crossing starts and ends
};

struct Tour {
    std::vector<math::HeadPose> poses;  // physical
    std::vector<int> visited;           // rooms the walker was in, in order of first visit
    std::vector<int> missed;            // rooms a door leads to that the tour could not reach
    std::vector<std::string> why;       // for each of `missed`: why, e.g. "door \"east\" is blocked by ..."
    int teleports = 0;
    double physical_distance = 0.0;  // m walked on the floor
    double virtual_distance = 0.0;   // m between successive virtual heads, portal jumps included
    // Closest approach of the head to the play area's edge (m; +inf without one).
    double closest_edge = std::numeric_limits<double>::infinity();
};

Result<Tour> plan_tour(const layout::Layout& layout, const TourOptions& options = {});

// Replays poses with a walker on the layout's `links` and fills visited,
// teleports and distances.
void replay(const layout::Layout& layout, const links::PortalLinks& links, Tour& tour);

}  // namespace impossible::design
