// The tour planner; see tour.hpp.
#include "design/tour.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

#include "design/obstacles.hpp"
#include "design/placement.hpp"
#include "math/rigid.hpp"
#include "walk/walker.hpp"

namespace impossible::design {
namespace {

class Planner {
public:
    Planner(const layout::Layout& layout, const TourOptions& o) : layout_(layout), o_(o) {
        placement_ = place_rooms(layout);
        if (layout.play_area) area_ = layout::outline(*layout.play_area);
        obstacles_ = room_obstacles(layout, placement_.links, o.grid.head_height);
        blocked_ = blocked_doors(layout, obstacles_, o.grid.body_radius, o.door_clearance);
    }

    Result<Tour> run();

private:
    const layout::Layout& layout_;
    TourOptions o_;
    Placement placement_;
    math::Polygon2 area_;
    std::vector<std::vector<Obstacle>> obstacles_;
    std::vector<BlockedDoor> blocked_;
    std::map<int, std::string> why_;  // why a room was left out, by room
    std::map<int, std::unique_ptr<RoomGrid>> grids_;
    std::vector<math::dvec3> physical_;  // the walk, as points on the physical floor at head height
    Tour result_;

    const RoomGrid& grid(int room) {
        auto& g = grids_[room];
        if (!g)
            g = std::make_unique<RoomGrid>(layout_, room, placement_.rooms[room].to_physical, area_, o_.grid,
                                           &obstacles_[static_cast<std::size_t>(room)]);
        return *g;
    }
    void emit(int room, const math::dvec3& virtual_point) {
        const math::dvec4 p = placement_.rooms[room].to_physical * math::dvec4(virtual_point, 1.0);
        physical_.push_back({p.x, p.y, p.z});
    }
    bool walk_to(int room, glm::dvec2& at, const glm::dvec2& to);
    std::optional<glm::dvec2> cross(int room, const glm::dvec2& at, int portal);
    std::string last_why_;  // why the last cross() failed
    void visit(int room, glm::dvec2& at);
    // Leaves `room` out, and the rooms beyond it with "it lies beyond ROOM: why".
    void miss(int room, const std::string& why, bool beyond = false);
    std::string door_reason(int portal, bool leaves_area) const;
};

// Why the tour could not take `portal` (or come back through its partner).
std::string Planner::door_reason(int portal, bool leaves_area) const {
    const layout::Portal& door = layout_.portals[static_cast<std::size_t>(portal)];
    const std::string& id = door.id;
    if (std::hypot(door.rect.normal.x, door.rect.normal.z) < 1e-6)
        return "door \"" + id + "\" lies in a floor or ceiling, which a walk does not pass";
    if (leaves_area) return "door \"" + id + "\" leads out of the play area";
    const int partner = layout_.portals[static_cast<std::size_t>(portal)].target;
    for (const BlockedDoor& b : blocked_)
        if (b.portal == portal || b.portal == partner)
            return "door \"" + layout_.portals[static_cast<std::size_t>(b.portal)].id + "\" is blocked by " +
                   obstacle_name(layout_, b.by);
    return "no free way to door \"" + id + "\" (walls, props, other doors or the play area's edge are in the way)";
}

bool Planner::walk_to(int room, glm::dvec2& at, const glm::dvec2& to) {
    if (!grid(room).free(at)) {  // e.g. just through a door with a prop behind it: step aside first
        const std::optional<glm::dvec2> aside = grid(room).nearest_free(at);
        if (!aside) return false;
        at = *aside;
        emit(room, {at.x, o_.grid.head_height, at.y});
    }
    const auto path = grid(room).find_path(at, to);
    if (!path) return false;
    for (std::size_t i = 1; i < path->size(); ++i) emit(room, {(*path)[i].x, o_.grid.head_height, (*path)[i].y});
    at = to;
    return true;
}

// From in front of `portal` (in `room`), through it: the point reached in the
// target's room, or nothing if the door cannot be reached or leaves the play area.
std::optional<glm::dvec2> Planner::cross(int room, const glm::dvec2& at_in, int portal) {
    const math::PortalRect& r = layout_.portals[portal].rect;
    const glm::dvec2 n = glm::normalize(glm::dvec2(r.normal.x, r.normal.z));
    const glm::dvec2 c{r.center.x, r.center.z};
    glm::dvec2 at = at_in;
    if (!walk_to(room, at, c + n * o_.door_clearance)) {
        last_why_ = door_reason(portal, false);
        return std::nullopt;
    }
    // Duck (or rise) to pass within the rectangle, then stand up again behind it.
    const double half = 0.5 * r.height * std::abs(r.up.y);
    const double h = o_.grid.head_height;
    const double y = std::clamp(h, r.center.y - half + 0.05, r.center.y + half - 0.05);
    const glm::dvec2 front = c + n * o_.door_clearance, back = c - n * o_.door_clearance;
    if (!area_.empty() &&
        !math::segment_inside(area_, to_floor(placement_.rooms[room].to_physical, {front.x, 0, front.y}),
                              to_floor(placement_.rooms[room].to_physical, {back.x, 0, back.y}))) {
        last_why_ = door_reason(portal, true);
        return std::nullopt;
    }
    emit(room, {front.x, y, front.y});
    emit(room, {back.x, y, back.y});
    const int target = layout_.portals[portal].target;
    const math::dvec4 p = placement_.links.transfer[portal] * math::dvec4(back.x, y, back.y, 1.0);
    emit(layout_.portals[target].room, {p.x, h, p.z});
    return glm::dvec2(p.x, p.z);
}

void Planner::miss(int room, const std::string& why, bool beyond) {
    result_.missed.push_back(room);
    why_.emplace(room, why);
    const std::string further =
        beyond ? why : "it lies beyond room \"" + layout_.rooms[static_cast<std::size_t>(room)].id + "\": " + why;
    for (std::size_t r = 0; r < placement_.rooms.size(); ++r)
        if (placement_.rooms[r].parent == room && placement_.rooms[r].reachable)
            miss(static_cast<int>(r), further, true);
}

void Planner::visit(int room, glm::dvec2& at) {
    const layout::Room& box = layout_.rooms[room];
    const glm::dvec2 centre{0.5 * (box.min.x + box.max.x), 0.5 * (box.min.z + box.max.z)};
    if (const auto c = grid(room).nearest_free(centre)) walk_to(room, at, *c);
    for (const int child : placement_.order) {
        const RoomPlacement& p = placement_.rooms[child];
        if (p.parent != room || child == layout_.start.room) continue;
        glm::dvec2 here = at;
        const std::size_t mark = physical_.size();
        const std::optional<glm::dvec2> inside = cross(room, here, p.via);
        if (!inside) {
            physical_.resize(mark);
            miss(child, last_why_);
            continue;
        }
        glm::dvec2 there = *inside;
        visit(child, there);
        const int back = layout_.portals[p.via].target;
        const std::optional<glm::dvec2> returned = cross(child, there, back);
        if (!returned) {  // no way back: leave the child out
            physical_.resize(mark);
            miss(child, "no way back: " + last_why_);
            continue;
        }
        at = *returned;
    }
}

Result<Tour> Planner::run() {
    const int start = layout_.start.room;
    const glm::dvec3& s = layout_.start.position;
    emit(start, {s.x, o_.grid.head_height, s.z});
    const std::optional<glm::dvec2> first = grid(start).nearest_free({s.x, s.z});
    if (!first) return Error{"the start room \"" + layout_.rooms[start].id + "\" has no room to walk"};
    glm::dvec2 at = *first;
    emit(start, {at.x, o_.grid.head_height, at.y});
    visit(start, at);

    // Resample to steps of at most o_.step, facing along the way.
    std::vector<math::HeadPose>& poses = result_.poses;
    double yaw = layout_.start.yaw_deg;
    for (std::size_t i = 0; i < physical_.size(); ++i) {
        const math::dvec3 a = i == 0 ? physical_[0] : physical_[i - 1], b = physical_[i];
        const double length = glm::distance(a, b);
        if (i > 0 && length < 1e-9) continue;
        if (std::hypot(b.x - a.x, b.z - a.z) > 1e-6) yaw = std::atan2(-(b.x - a.x), -(b.z - a.z)) * 180.0 / math::kPi;
        const int steps = i == 0 ? 1 : std::max(1, static_cast<int>(std::ceil(length / o_.step)));
        for (int k = 1; k <= steps; ++k) {
            const math::dvec3 p = i == 0 ? b : a + (b - a) * (double(k) / steps);
            poses.push_back(math::HeadPose{p, std::round(yaw * 1e4) / 1e4 + 0.0, 0.0, 0.0});
        }
    }
    replay(layout_, placement_.links, result_);
    result_.missed.clear();
    for (const int r : placement_.order)
        if (std::find(result_.visited.begin(), result_.visited.end(), r) == result_.visited.end()) {
            result_.missed.push_back(r);
            const auto why = why_.find(r);
            result_.why.push_back(why != why_.end() ? why->second : "the walker never entered it on the planned way");
        }
    return result_;
}

}  // namespace

void replay(const layout::Layout& layout, const links::PortalLinks& links, Tour& tour) {
    tour.visited.clear();
    tour.teleports = 0;
    tour.physical_distance = tour.virtual_distance = 0.0;
    tour.closest_edge = std::numeric_limits<double>::infinity();
    const math::Polygon2 area = layout.play_area ? layout::outline(*layout.play_area) : math::Polygon2{};
    walk::Walker walker(layout, layout.start.room, std::make_shared<const links::PortalLinks>(links));
    for (std::size_t i = 0; i < tour.poses.size(); ++i) {
        const math::dvec3 before = walker.position();
        tour.teleports += static_cast<int>(walker.step(tour.poses[i]).size());
        if (i > 0) {
            tour.physical_distance += glm::distance(tour.poses[i].position, tour.poses[i - 1].position);
            tour.virtual_distance += glm::distance(walker.position(), before);
        }
        if (std::find(tour.visited.begin(), tour.visited.end(), walker.room()) == tour.visited.end())
            tour.visited.push_back(walker.room());
        if (!area.empty()) {
            const glm::dvec2 p{tour.poses[i].position.x, tour.poses[i].position.z};
            const double d = math::distance_to_boundary(area, p);
            tour.closest_edge = std::min(tour.closest_edge, math::contains(area, p, 0.0) ? d : -d);
        }
    }
}

Result<Tour> plan_tour(const layout::Layout& layout, const TourOptions& options) {
    if (!layout.changes.empty()) return plan_tour_with_changes(layout, options);
    return Planner(layout, options).run();
}

}  // namespace impossible::design
