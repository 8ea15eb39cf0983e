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

// A line the tour says about its walk, before pose `pose` (a comment of
// the path file): where it waits for a change and where one is made.
struct TourNote {
    std::size_t pose = 0;
    std::string text;
};

struct Tour {
    std::vector<math::HeadPose> poses;  // physical
    std::vector<TourNote> notes;        // only with changes, in pose order
    std::vector<int> changes;           // the changes the walk makes, in the order made
    std::vector<int> visited;           // rooms the walker was in, in order of first visit
    std::vector<int> missed;            // rooms a door leads to that the tour could not reach
    std::vector<std::string> why;       // for each of `missed`: why, e.g. "door \"east\" is blocked by ..."
    int teleports = 0;
    double physical_distance = 0.0;  // m walked on the floor
    double virtual_distance = 0.0;   // m between successive virtual heads, portal jumps included
    // Closest approach of the head to the play area's edge (m; +inf without one).
    double closest_edge = std::numeric_limits<double>::infinity();
};

// A layout with `changes` is planned by plan_tour_with_changes.
Result<Tour> plan_tour(const layout::Layout& layout, const TourOptions& options = {});

// The tour of a layout with changes (layout-format.md, "Changes while
// walking"; tour_changes.cpp). The walk is simulated pose by pose with
// changes::ChangeWalker (the seen test on render's default eyes, 90 poses a
// second), so the changes are armed and made as `walk` makes them. From
// where the head is, it walks to the nearest room not yet visited that
// doors lead to under the pairing in force (to the door, through it, on to
// the room's free point nearest its centre; rooms whose way passes the
// room of a change it would arm come last), and plans again whenever a
// change is made. With no such room left and rooms still to visit, it
// walks to the room of the first change that can be armed, stands still
// until its `time`, and turns on the spot (then on other spots, then
// looking down) until the change is made; `notes` say where. Rooms that
// only changes lead to (design/report_changes.hpp) count as reachable. An
// error names the change and the room when a room the tour must visit
// needs a change that cannot happen on its route (its room is never
// reached, its `after` never happens, its `time` is more than
// kMaxTourWait seconds on, or an eye sees one of its doors wherever it
// stands and turns).
inline constexpr double kMaxTourWait = 300.0;
Result<Tour> plan_tour_with_changes(const layout::Layout& layout, const TourOptions& options = {});

// Replays poses with a walker on the layout's `links` and fills visited,
// teleports and distances.
void replay(const layout::Layout& layout, const links::PortalLinks& links, Tour& tour);

}  // namespace impossible::design
