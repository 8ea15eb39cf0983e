// Prism rooms built in code for the tracer's tests (layout-format.md, "Rooms
// of any shape"): an L, a turned square, a curved corridor, and their walls'
// normals worked out by hand (not through layout::face_frame).
#pragma once

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "common/layouts.hpp"
#include "layout/layout.hpp"

namespace impossible::trace::test {

using glm::dvec2;

// An L in (x, z), counter-clockwise: the square [0, 4]² without its
// notch [2, 4] × [2, 4]. Walls: 0 z = 0, 1 x = 4, 2 z = 2 (x 4 → 2),
// 3 x = 2 (z 2 → 4), 4 z = 4, 5 x = 0; corner 3, (2, 2), is the concave one.
inline std::vector<dvec2> l_floor() { return {{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}}; }

// A square of side 2·half about `center`, turned by `deg` about +y, counter-
// clockwise in (x, z) unless `clockwise`.
inline std::vector<dvec2> turned_square(dvec2 center, double half, double deg, bool clockwise = false) {
    const double a = deg * std::numbers::pi / 180.0;
    const dvec2 u(std::cos(a), std::sin(a)), v(-std::sin(a), std::cos(a));
    std::vector<dvec2> c = {center + half * (-u - v), center + half * (u - v), center + half * (u + v),
                            center + half * (-u + v)};
    if (clockwise) c = {c[3], c[2], c[1], c[0]};
    return c;
}

// A corridor bent through 90° about the origin between radii r0 and r1: 12
// corners along the outer arc (angle 0 → 90°), then 12 back along the inner
// one: 24 walls, counter-clockwise in (x, z). Walls 0..10 are the outer
// arc's, 11 the end at 90°, 12..22 the inner arc's, 23 the end at 0°.
inline std::vector<dvec2> curved_corridor(double r0 = 3.0, double r1 = 4.5) {
    std::vector<dvec2> c;
    for (int k = 0; k < 12; ++k) {
        const double a = (std::numbers::pi / 2.0) * k / 11.0;
        c.push_back(r1 * dvec2(std::cos(a), std::sin(a)));
    }
    for (int k = 11; k >= 0; --k) {
        const double a = (std::numbers::pi / 2.0) * k / 11.0;
        c.push_back(r0 * dvec2(std::cos(a), std::sin(a)));
    }
    return c;
}

// The unit normal of wall i into the room, by hand: the left of corner i →
// corner i + 1 in (x, z) for a counter-clockwise floor, the right otherwise.
inline glm::dvec3 inward_normal(const std::vector<dvec2>& floor, int i, bool clockwise = false) {
    const dvec2 a = floor[static_cast<std::size_t>(i)];
    const dvec2 b = floor[(static_cast<std::size_t>(i) + 1) % floor.size()];
    const dvec2 e = (b - a) / std::hypot(b.x - a.x, b.y - a.y);
    const double s = clockwise ? -1.0 : 1.0;
    return {-s * e.y, 0.0, s * e.x};
}

// The midpoint of wall i at height y.
inline glm::dvec3 wall_point(const std::vector<dvec2>& floor, int i, double y, double along = 0.5) {
    const dvec2 a = floor[static_cast<std::size_t>(i)];
    const dvec2 b = floor[(static_cast<std::size_t>(i) + 1) % floor.size()];
    const dvec2 p = a + along * (b - a);
    return {p.x, y, p.y};
}

// One prism room over `floor`, y from 0 to 3, the head in it.
inline layout::Layout prism_layout(std::vector<dvec2> floor, double y0 = 0.0, double y1 = 3.0) {
    layout::Layout l;
    l.source = "<test>";
    l.rooms.push_back(impossible::test::prism_room("prism", std::move(floor), y0, y1));
    l.start.room = 0;
    return l;
}

}  // namespace impossible::trace::test
