// Layouts built in code for the walker tests (no loader involved).
#pragma once

#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "common/layouts.hpp"
#include "layout/layout.hpp"
#include "math/pose.hpp"

namespace impossible::walk::testing {

// A head at p looking along yaw, level.
inline math::HeadPose at(glm::dvec3 p, double yaw = 0.0) { return math::HeadPose{p, yaw, 0.0, 0.0}; }
// No portals crossed.
inline std::vector<int> none() { return {}; }

using test::add_room;
using test::make_rect;

// Adds portals a (in room ra) and b (in room rb), linked to each other;
// returns the index of a (b is the next one).
inline int add_pair(layout::Layout& l, const std::string& id_a, int ra, const math::PortalRect& a,
                    const std::string& id_b, int rb, const math::PortalRect& b) {
    const int ia = static_cast<int>(l.portals.size());
    l.portals.push_back(layout::Portal{id_a, ra, a, ia + 1});
    l.portals.push_back(layout::Portal{id_b, rb, b, ia});
    return ia;
}

inline layout::Layout empty_layout(const std::string& name) {
    layout::Layout l;
    l.source = "<" + name + ">";
    l.name = name;
    return l;
}

// "hall" and "annex" side by side, one coincident doorway at x = 2 (M = I).
inline layout::Layout doorway() {
    layout::Layout l = empty_layout("doorway");
    const int hall = add_room(l, "hall", {-2, 0, -2}, {2, 3, 2});
    const int annex = add_room(l, "annex", {2, 0, -2}, {6, 3, 2});
    add_pair(l, "hall_east", hall, make_rect({2, 1.1, 0}, {-1, 0, 0}, 1.0, 2.2), "annex_west", annex,
             make_rect({2, 1.1, 0}, {1, 0, 0}, 1.0, 2.2));
    l.start = {hall, {0, 1.6, 1}, 0.0};
    return l;
}

// "hall" with a door in its +x wall at x = 2 whose partner stands in the -z
// wall of "annex" (far away, x 10..14), so the door turns what passes it by
// 90°: the hall's +x becomes the annex's +z.
inline layout::Layout turned_door() {
    layout::Layout l = empty_layout("turned door");
    const int hall = add_room(l, "hall", {-2, 0, -2}, {2, 3, 2});
    const int annex = add_room(l, "annex", {10, 0, -2}, {14, 3, 2});
    add_pair(l, "hall_east", hall, make_rect({2, 1.1, 0}, {-1, 0, 0}, 1.0, 2.2), "annex_north", annex,
             make_rect({12, 1.1, -2}, {0, 0, 1}, 1.0, 2.2));
    l.start = {hall, {0, 1.6, 1}, 0.0};
    return l;
}

// A pair whose transfer matrix is not exactly representable: A in "r0"
// turned 37°, B in "r1" turned -71.3°, both at irrational-ish centres.
inline layout::Layout skewed_pair() {
    layout::Layout l = empty_layout("skewed");
    const int r0 = add_room(l, "r0", {-5, 0, -5}, {5, 3, 5});
    const int r1 = add_room(l, "r1", {-20, 0, -20}, {20, 3, 20});
    const glm::dvec3 na = math::rotation_y_deg(37.0) * glm::dvec3(0, 0, 1);
    const glm::dvec3 nb = math::rotation_y_deg(-71.3) * glm::dvec3(0, 0, 1);
    add_pair(l, "a", r0, make_rect({0.12345678901, 1.1, -0.76543210987}, na, 0.9, 2.1), "b", r1,
             make_rect({14.142135623730951, 1.3183098861837907, -9.42477796076938}, nb, 0.9, 2.1));
    l.start = {r0, {0, 1.6, 1}, 0.0};
    return l;
}

}  // namespace impossible::walk::testing
