// The tour of a layout with changes, walking; see tour.hpp
// (plan_tour_with_changes) and tour_changes.hpp.
#include "design/tour_changes.hpp"

#include <algorithm>
#include <cmath>
#include <deque>

#include "math/rigid.hpp"

namespace impossible::design::detail {

namespace {

double path_rounded(double v) { return std::round(v * 1e4) / 1e4 + 0.0; }  // as the path file writes it

}  // namespace

void ChangePlanner::restage(bool changed) {
    const layout::Layout& l = sim_.current();
    const links::PortalLinks& links = sim_.links();
    const std::size_t n = l.rooms.size();
    const Stage before = std::move(stage_);
    stage_ = Stage{};
    stage_.reachable.assign(n, 0);
    stage_.to_physical.assign(n, math::dmat4(1.0));
    stage_.parent.assign(n, -1), stage_.via.assign(n, -1), stage_.doors.assign(n, 0);
    std::vector<math::dmat4> w(n, math::dmat4(1.0));
    const int start = sim_.room();
    stage_.root = start;
    w[start] = sim_.walker().physical_to_virtual();
    stage_.to_physical[start] = math::rigid_inverse(w[start]);
    stage_.reachable[start] = 1;
    std::deque<int> queue{start};
    while (!queue.empty()) {
        const int room = queue.front();
        queue.pop_front();
        stage_.order.push_back(room);
        for (const int p : links.room_portals[room]) {
            if (l.portals[p].kind != layout::PortalKind::Door) continue;
            const int next = l.portals[l.portals[p].target].room;
            if (stage_.reachable[next]) continue;
            w[next] = math::orthonormalize_rigid(links.transfer[p] * w[room]);
            stage_.to_physical[next] = math::rigid_inverse(w[next]);
            stage_.reachable[next] = 1, stage_.parent[next] = room, stage_.via[next] = p;
            stage_.doors[next] = stage_.doors[room] + 1;
            queue.push_back(next);
        }
    }
    if (changed) {
        obstacles_ = room_obstacles(l, links, o_.grid.head_height);
        grids_.clear();
        failed_.clear();
        return;
    }
    // The same pairing from another room: a room's grid stays where its
    // place on the floor does (always, unless doors place it differently).
    for (auto it = grids_.begin(); it != grids_.end();)
        if (math::max_abs_difference(before.to_physical[it->first], stage_.to_physical[it->first]) > 1e-9)
            it = grids_.erase(it);
        else
            ++it;
}

const RoomGrid& ChangePlanner::grid(int room) {
    auto& g = grids_[room];
    if (!g)
        g = std::make_unique<RoomGrid>(sim_.current(), room, stage_.to_physical[room], area_, o_.grid,
                                       &obstacles_[static_cast<std::size_t>(room)]);
    return *g;
}

// One pose, as the path file will hold it, walked with the changes.
Went ChangePlanner::pose(const math::HeadPose& raw) {
    const math::HeadPose p{{path_rounded(raw.position.x), path_rounded(raw.position.y), path_rounded(raw.position.z)},
                           path_rounded(raw.yaw_deg),
                           path_rounded(raw.pitch_deg),
                           0.0};
    const math::dvec3 before = sim_.walker().position();
    const bool first = t_.poses.empty();
    t_.poses.push_back(p);
    const changes::ChangeStep s = sim_.step(p);
    t_.teleports += static_cast<int>(s.teleports.size());
    if (!first) {
        t_.physical_distance += glm::distance(p.position, t_.poses[t_.poses.size() - 2].position);
        t_.virtual_distance += glm::distance(sim_.walker().position(), before);
    }
    if (!visited(sim_.room())) t_.visited.push_back(sim_.room());
    if (!area_.empty()) {
        const glm::dvec2 q{p.position.x, p.position.z};
        const double d = math::distance_to_boundary(area_, q);
        t_.closest_edge = std::min(t_.closest_edge, math::contains(area_, q, 0.0) ? d : -d);
    }
    if (s.changes.empty()) return Went::Ok;
    for (const int c : s.changes) {
        t_.changes.push_back(c);
        t_.notes.push_back({t_.poses.size() - 1, "change " + base_.changes[static_cast<std::size_t>(c)].id +
                                                     " is made here, in " + base_.rooms[sim_.room()].id + " (frame " +
                                                     std::to_string(t_.poses.size() - 1) + ")"});
    }
    restage();
    return Went::Changed;
}

// On to `point` of `room`'s coordinates, in steps of at most o_.step,
// facing the way it goes (or keeping the yaw, face false).
Went ChangePlanner::go(int room, const math::dvec3& point, bool face) {
    if (t_.poses.size() > kMaxPoses) return Went::Failed;
    const math::dvec4 q = stage_.to_physical[room] * math::dvec4(point, 1.0);
    const math::dvec3 b{q.x, q.y, q.z}, a = last_;
    const double length = glm::distance(a, b);
    if (length < 1e-9) return Went::Ok;
    if (face && std::hypot(b.x - a.x, b.z - a.z) > 1e-6)
        yaw_ = std::atan2(-(b.x - a.x), -(b.z - a.z)) * 180.0 / math::kPi;
    const int steps = std::max(1, static_cast<int>(std::ceil(length / o_.step)));
    for (int k = 1; k <= steps; ++k) {
        last_ = a + (b - a) * (double(k) / steps);
        if (pose({last_, yaw_, 0.0, 0.0}) == Went::Changed) return Went::Changed;
    }
    return Went::Ok;
}

Went ChangePlanner::walk_to(int room, glm::dvec2& at, const glm::dvec2& to) {
    const double h = o_.grid.head_height;
    if (!grid(room).free(at)) {
        const std::optional<glm::dvec2> aside = grid(room).nearest_free(at);
        if (!aside) return Went::Failed;
        at = *aside;
        if (const Went w = go(room, {at.x, h, at.y}); w != Went::Ok) return w;
    }
    const auto path = grid(room).find_path(at, to);
    if (!path) return Went::Failed;
    for (std::size_t i = 1; i < path->size(); ++i)
        if (const Went w = go(room, {(*path)[i].x, h, (*path)[i].y}); w != Went::Ok) return w;
    at = to;
    return Went::Ok;
}

// From `at` in `room` through `door` (of the current layout), ducking to
// fit, to door_clearance behind it: `at` is then in the target's room.
Went ChangePlanner::cross(int room, glm::dvec2& at, int door, std::string& why) {
    const layout::Layout& l = sim_.current();
    const math::PortalRect& r = l.portals[door].rect;
    const std::string& id = l.portals[door].id;
    if (std::hypot(r.normal.x, r.normal.z) < 1e-6) {
        why = "door \"" + id + "\" lies in a floor or ceiling, which a walk does not pass";
        return Went::Failed;
    }
    const glm::dvec2 n = glm::normalize(glm::dvec2(r.normal.x, r.normal.z)), c{r.center.x, r.center.z};
    const glm::dvec2 front = c + n * o_.door_clearance, back = c - n * o_.door_clearance;
    const Went w = walk_to(room, at, front);
    if (w == Went::Failed)
        why = "no free way to door \"" + id + "\" (walls, props, other doors or the play area's edge are in the way)";
    if (w != Went::Ok) return w;
    if (!area_.empty() && !math::segment_inside(area_, to_floor(stage_.to_physical[room], {front.x, 0, front.y}),
                                                to_floor(stage_.to_physical[room], {back.x, 0, back.y}))) {
        why = "door \"" + id + "\" leads out of the play area";
        return Went::Failed;
    }
    const double half = 0.5 * r.height * std::abs(r.up.y), h = o_.grid.head_height;
    const double y = std::clamp(h, r.center.y - half + 0.05, r.center.y + half - 0.05);
    const int target = l.portals[door].target;
    const math::dvec4 p = sim_.links().transfer[door] * math::dvec4(back.x, y, back.y, 1.0);
    for (const math::dvec3& point : {math::dvec3(front.x, y, front.y), math::dvec3(back.x, y, back.y)})
        if (const Went went = go(room, point); went != Went::Ok) return went;
    const int next = l.portals[target].room;
    if (const Went went = go(next, {p.x, h, p.z}); went != Went::Ok) return went;
    at = {p.x, p.z};
    return Went::Ok;
}

// From the head's room along the stage's doors to `target`'s free point
// nearest its centre.
Went ChangePlanner::leg(int target, std::string& why) {
    std::vector<int> rooms;
    for (int r = target; r >= 0; r = stage_.parent[r]) rooms.push_back(r);
    std::reverse(rooms.begin(), rooms.end());
    glm::dvec2 at = here();
    for (std::size_t k = 1; k < rooms.size(); ++k)
        if (const Went w = cross(rooms[k - 1], at, stage_.via[rooms[k]], why); w != Went::Ok) return w;
    if (sim_.room() != target) {
        why = "the walker did not come into it on the planned way";
        return Went::Failed;
    }
    const layout::Room& box = sim_.current().rooms[target];
    const glm::dvec2 centre{0.5 * (box.min.x + box.max.x), 0.5 * (box.min.z + box.max.z)};
    if (const auto c = grid(target).nearest_free(centre))
        return walk_to(target, at, *c) == Went::Changed ? Went::Changed : Went::Ok;
    return Went::Ok;
}

// The nearest room to visit that doors lead to with the pairing in force.
// Rooms whose way there passes the `enter` room of a change that entering
// would arm (not made, not armed, its `after` made) come last: arming a
// change may re-pair doors on the way, and cut off rooms not yet visited.
int ChangePlanner::next_room() const {
    const std::vector<changes::ChangeStatus>& status = sim_.changes().status();
    std::vector<char> arms(base_.rooms.size(), 0);
    for (std::size_t c = 0; c < base_.changes.size(); ++c) {
        const layout::ChangeWhen& when = base_.changes[c].when;
        if (status[c].made_frame >= 0 || status[c].armed || when.enter < 0) continue;
        if (when.after < 0 || status[static_cast<std::size_t>(when.after)].made_frame >= 0) arms[when.enter] = 1;
    }
    const auto arming = [&](int room) {
        for (int r = room; r >= 0 && r != sim_.room(); r = stage_.parent[r])
            if (arms[r]) return true;
        return false;
    };
    for (const bool late : {false, true})
        for (const int r : stage_.order)
            if (goal_[r] && !visited(r) && !failed_.count(r) && arming(r) == late) return r;
    return -1;
}

}  // namespace impossible::design::detail
