// The planner of plan_tour_with_changes (tour.hpp), shared by its two
// files: tour_changes.cpp walks (the stage of the pairing in force, poses,
// ways to rooms), tour_waits.cpp waits for changes and ends the tour.
#pragma once

#include <algorithm>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "changes/change_walker.hpp"
#include "design/obstacles.hpp"
#include "design/report_changes.hpp"
#include "design/room_grid.hpp"
#include "design/tour.hpp"
#include "layout/path_file.hpp"

namespace impossible::design::detail {

// What a stretch of the walk came to.
enum class Went { Ok, Changed, Failed };

// Poses at most (11 minutes at 90 a second): a path file of them stays within
// layout::kMaxPathFileBytes (4 MiB) at up to 70 bytes a line.
inline constexpr std::size_t kMaxPoses = 60'000;
inline constexpr double kTurnDeg = 15.0;

// Where each room lies on the physical floor with the pairing in force,
// breadth first from the head's room with the walker's W.
struct Stage {
    std::vector<char> reachable;
    std::vector<math::dmat4> to_physical;
    std::vector<int> parent, via, doors;  // via: a door of the current layout
    std::vector<int> order;
    int root = -1;  // the head's room it was made from
};

class ChangePlanner {
public:
    ChangePlanner(const layout::Layout& layout, const TourOptions& o) : base_(layout), o_(o), sim_(layout) {
        if (layout.play_area) area_ = layout::outline(*layout.play_area);
        goal_ = changes_reach(layout).reachable;
        given_up_.assign(layout.changes.size(), std::string());
    }
    Result<Tour> run();

private:
    const layout::Layout& base_;
    TourOptions o_;
    changes::ChangeWalker sim_;
    math::Polygon2 area_;
    std::vector<char> goal_;
    std::vector<std::string> given_up_;  // per change: why it cannot happen on the route ("" while it may)
    Stage stage_;
    std::vector<std::vector<Obstacle>> obstacles_;
    std::map<int, std::unique_ptr<RoomGrid>> grids_;
    std::map<int, std::string> failed_;  // rooms the tour could not walk to with the pairing in force, and why
    std::map<int, std::string> why_;     // the same, kept across changes
    math::dvec3 last_{0.0};
    double yaw_ = 0.0;
    Tour t_;

    // The stage from the head's room; a new pairing (`changed`) also forgets
    // the rooms the tour could not walk to.
    void restage(bool changed = true);
    const RoomGrid& grid(int room);
    bool visited(int room) const { return std::find(t_.visited.begin(), t_.visited.end(), room) != t_.visited.end(); }
    glm::dvec2 here() const { return {sim_.walker().position().x, sim_.walker().position().z}; }
    Went pose(const math::HeadPose& p);
    Went go(int room, const math::dvec3& point, bool face = true);
    Went walk_to(int room, glm::dvec2& at, const glm::dvec2& to);
    Went cross(int room, glm::dvec2& at, int door, std::string& why);
    Went leg(int target, std::string& why);
    int next_room() const;
    int next_change();
    Went wait_for(int change);
    Went turn_round(double pitch);
    void settle();
    std::string door_ids(int change) const;
    std::string never_why(int change) const;
    Result<Tour> finish();
};

}  // namespace impossible::design::detail
