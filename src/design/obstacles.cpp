// The props in a walker's way and the doors they block; see obstacles.hpp.
#include "design/obstacles.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

#include "design/placement.hpp"
#include "math/polygon.hpp"
#include "walk/objects.hpp"

namespace impossible::design {
namespace {

struct Bounds {
    glm::dvec3 lo{INFINITY}, hi{-INFINITY};
    void add(const glm::dvec3& p) { lo = glm::min(lo, p), hi = glm::max(hi, p); }
};

// The prop's box in the layout's coordinates as written (a model: its placed triangles').
Bounds listed_bounds(const layout::Prop& prop) {
    Bounds b;
    if (const auto* box = std::get_if<layout::BoxProp>(&prop)) {
        b.add(box->min), b.add(box->max);
        return b;
    }
    const auto& model = std::get<layout::GltfProp>(prop);
    for (const assets::ModelTriangle& t : model.triangles)
        for (const glm::dvec3& v : t.position) b.add(layout::place_model_point(model, v));
    return b;
}

void add(std::vector<Obstacle>& out, const Bounds& b, int room, int prop, bool resting, double head_height) {
    if (b.lo.x > b.hi.x || b.lo.y > head_height + 0.2) return;
    out.push_back({{b.lo.x, b.lo.z}, {b.hi.x, b.hi.z}, room, prop, resting});
}

// A moving prop's box at `time`, in the room it is in then.
void add_moving(std::vector<std::vector<Obstacle>>& out, const walk::ObjectSet& set, int k, const Bounds& listed,
                double time, bool resting, double head_height) {
    const walk::PropState s = walk::walk_prop(set, k, time);
    if (s.room < 0 || s.room >= static_cast<int>(out.size())) return;
    Bounds b;
    for (int c = 0; c < 8; ++c) {
        const glm::dvec3 p{c & 1 ? listed.hi.x : listed.lo.x, c & 2 ? listed.hi.y : listed.lo.y,
                           c & 4 ? listed.hi.z : listed.lo.z};
        b.add(glm::dvec3(s.w * glm::dvec4(p + s.offset, 1.0)));
    }
    const walk::DynamicProp& d = set.props[static_cast<std::size_t>(k)];
    add(out[static_cast<std::size_t>(s.room)], b, d.room, d.index, resting, head_height);
}

// Whether the rectangle comes within `r` of the segment ab.
bool near_segment(const Obstacle& o, const glm::dvec2& a, const glm::dvec2& b, double r) {
    const glm::dvec2 lo = o.lo - r, hi = o.hi + r;
    const glm::dvec2 slo = glm::min(a, b), shi = glm::max(a, b);
    if (shi.x < lo.x || slo.x > hi.x || shi.y < lo.y || slo.y > hi.y) return false;
    const double length = glm::distance(a, b);
    const int steps = std::max(1, static_cast<int>(std::ceil(length / 0.01)));
    for (int s = 0; s <= steps; ++s)
        if (obstacle_distance(a + (b - a) * (double(s) / steps), o) < r) return true;
    return false;
}

}  // namespace

double obstacle_distance(const glm::dvec2& p, const Obstacle& o) {
    const double dx = std::max({o.lo.x - p.x, 0.0, p.x - o.hi.x});
    const double dz = std::max({o.lo.y - p.y, 0.0, p.y - o.hi.y});
    return std::hypot(dx, dz);
}

std::vector<std::vector<Obstacle>> room_obstacles(const layout::Layout& layout, const links::PortalLinks& links,
                                                  double head_height) {
    std::vector<std::vector<Obstacle>> out(layout.rooms.size());
    bool moving = false;
    for (std::size_t r = 0; r < layout.rooms.size(); ++r)
        for (std::size_t k = 0; k < layout.rooms[r].props.size(); ++k) {
            const layout::Prop& prop = layout.rooms[r].props[k];
            if (!layout::prop_motion(prop).keys.empty()) {
                moving = true;
                continue;
            }
            add(out[r], listed_bounds(prop), static_cast<int>(r), static_cast<int>(k), false, head_height);
        }
    if (!moving) return out;
    const walk::ObjectSet set = walk::build_object_set(layout, links);
    for (std::size_t k = 0; k < set.props.size(); ++k) {
        const walk::DynamicProp& d = set.props[k];
        if (d.motion.keys.empty()) continue;
        const Bounds listed = listed_bounds(layout.rooms[static_cast<std::size_t>(d.room)].props[d.index]);
        add_moving(out, set, static_cast<int>(k), listed, 0.0, false, head_height);
        if (!d.motion.loop && d.motion.keys.size() > 1)
            add_moving(out, set, static_cast<int>(k), listed, d.motion.keys.back().t, true, head_height);
    }
    return out;
}

std::vector<Obstacle> listed_obstacles(const layout::Layout& layout, int room, double head_height) {
    std::vector<Obstacle> out;
    const auto& props = layout.rooms[static_cast<std::size_t>(room)].props;
    for (std::size_t k = 0; k < props.size(); ++k)
        add(out, listed_bounds(props[k]), room, static_cast<int>(k), false, head_height);
    return out;
}

std::string obstacle_name(const layout::Layout& layout, const Obstacle& o) {
    const layout::Prop& prop = layout.rooms[static_cast<std::size_t>(o.listed_room)].props[o.prop];
    const std::string& id = layout::prop_id(prop);
    std::string out = "rooms[" + std::to_string(o.listed_room) + "].props[" + std::to_string(o.prop) + "]";
    if (!id.empty()) out += " (" + id + ")";
    if (o.resting) out += " where its motion leaves it";
    return out;
}

std::vector<BlockedDoor> blocked_doors(const layout::Layout& layout,
                                       const std::vector<std::vector<Obstacle>>& obstacles, double body_radius,
                                       double clearance) {
    std::vector<BlockedDoor> out;
    for (std::size_t i = 0; i < layout.portals.size(); ++i) {
        const layout::Portal& p = layout.portals[i];
        if (p.kind != layout::PortalKind::Door || p.target < 0) continue;
        const glm::dvec2 n{p.rect.normal.x, p.rect.normal.z};
        if (glm::length(n) < 1e-6) continue;  // a trapdoor is not walked through
        const glm::dvec2 c{p.rect.center.x, p.rect.center.z};
        const glm::dvec2 front = c + glm::normalize(n) * clearance;
        for (const Obstacle& o : obstacles[static_cast<std::size_t>(p.room)]) {
            if (!near_segment(o, c, front, body_radius)) continue;
            out.push_back({static_cast<int>(i), o});
            break;
        }
    }
    return out;
}

const BlockedDoor* blocked_on_way(const layout::Layout& layout, const Placement& placement,
                                  const std::vector<BlockedDoor>& blocked, int room) {
    const auto find = [&](int portal) -> const BlockedDoor* {
        for (const BlockedDoor& b : blocked)
            if (b.portal == portal) return &b;
        return nullptr;
    };
    std::vector<int> way;  // rooms from `room` back to the start
    for (int r = room; r >= 0 && static_cast<int>(way.size()) <= static_cast<int>(layout.rooms.size());
         r = placement.rooms[static_cast<std::size_t>(r)].parent)
        way.push_back(r);
    for (auto it = way.rbegin(); it != way.rend(); ++it) {
        const int via = placement.rooms[static_cast<std::size_t>(*it)].via;
        if (via < 0) continue;
        if (const BlockedDoor* b = find(via)) return b;
        if (const BlockedDoor* b = find(layout.portals[static_cast<std::size_t>(via)].target)) return b;
    }
    return nullptr;
}

}  // namespace impossible::design
