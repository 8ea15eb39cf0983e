#include "layout/room_shape.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <glm/geometric.hpp>

namespace impossible::layout {

int wall_count(const Room& room) { return static_cast<int>(room.floor.size()); }

int face_count(const Room& room) { return is_prism(room) ? 2 + wall_count(room) : kFaceCount; }

std::string face_name(const Room& room, int face) {
    if (face == static_cast<int>(Face::Floor)) return "floor";
    if (face == static_cast<int>(Face::Ceiling)) return "ceiling";
    if (is_prism(room)) return "wall" + std::to_string(face - 2);
    return kFaceNames[static_cast<std::size_t>(face)];
}

math::Polygon2 floor_outline(const Room& room) {
    if (!is_prism(room)) return math::rectangle({room.min.x, room.min.z}, {room.max.x, room.max.z});
    math::Polygon2 poly = room.floor;
    if (math::signed_area(poly) < 0.0) std::reverse(poly.begin(), poly.end());
    return poly;
}

bool floor_convex(const Room& room) {
    if (!is_prism(room)) return true;
    const math::Polygon2 poly = floor_outline(room);
    const std::size_t n = poly.size();
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2 e0 = poly[(i + 1) % n] - poly[i];
        const glm::dvec2 e1 = poly[(i + 2) % n] - poly[(i + 1) % n];
        if (e0.x * e1.y - e0.y * e1.x < 0.0) return false;  // a right turn: a reflex corner
    }
    return true;
}

Wall wall(const Room& room, int index) {
    assert(is_prism(room) && index >= 0 && index < wall_count(room));
    const std::size_t n = room.floor.size();
    const auto i = static_cast<std::size_t>(index);
    Wall w{room.floor[i], room.floor[(i + 1) % n], {}};
    const glm::dvec2 along = glm::normalize(w.b - w.a);
    // Counter-clockwise in (x, z) the interior lies to the left of a→b in
    // those axes: (-dz, dx); clockwise, to the right.
    const double sign = math::signed_area(room.floor) > 0.0 ? 1.0 : -1.0;
    w.inward = sign * glm::dvec2(-along.y, along.x);
    return w;
}

std::vector<int> crossable_walls(const Room& room) {
    std::vector<int> out;
    if (!is_prism(room)) return out;
    const glm::dvec2 extent(room.max.x - room.min.x, room.max.z - room.min.z);
    const double scale = 1.0 + std::abs(room.min.x) + std::abs(room.min.z) + extent.x + extent.y;
    for (int i = 0; i < wall_count(room); ++i) {
        const Wall w = wall(room, i);
        const bool behind = std::any_of(room.floor.begin(), room.floor.end(), [&](const glm::dvec2& c) {
            return glm::dot(c - w.a, w.inward) < -1e-9 * scale;
        });
        if (behind) out.push_back(i);
    }
    return out;
}

namespace {

FaceFrame side_frame(const glm::dvec3& normal, const glm::dvec3& origin) {
    FaceFrame f;
    f.normal = normal;
    f.t_axis = {0.0, 1.0, 0.0};
    f.s_axis = glm::cross(-normal, f.t_axis);  // a viewer facing the face looks along -normal
    f.origin = origin;
    return f;
}

}  // namespace

FaceFrame face_frame(const Room& room, int face) {
    assert(face >= 0 && face < face_count(room));
    FaceFrame f;
    const math::Polygon2 floor = floor_outline(room);
    if (face == static_cast<int>(Face::Floor) || face == static_cast<int>(Face::Ceiling)) {
        const bool is_floor = face == static_cast<int>(Face::Floor);
        f.origin = {0.0, is_floor ? room.min.y : room.max.y, 0.0};
        f.normal = {0.0, is_floor ? 1.0 : -1.0, 0.0};
        f.s_axis = {is_floor ? 1.0 : -1.0, 0.0, 0.0};
        f.t_axis = {0.0, 0.0, -1.0};
        for (const glm::dvec2& c : floor) f.outline.push_back({is_floor ? c.x : -c.x, -c.y});
        if (math::signed_area(f.outline) < 0.0) std::reverse(f.outline.begin(), f.outline.end());
        return f;
    }
    if (!is_prism(room)) {
        static const glm::dvec3 normals[] = {{1, 0, 0}, {-1, 0, 0}, {0, 0, 1}, {0, 0, -1}};
        const glm::dvec3 n = normals[face - 2];
        const double plane = face == 2 ? room.min.x : face == 3 ? room.max.x : face == 4 ? room.min.z : room.max.z;
        f = side_frame(n, n * (plane * glm::dot(n, glm::dvec3(1.0))));
        const glm::dvec3 lo{room.min.x, room.min.y, room.min.z};
        const glm::dvec3 hi{room.max.x, room.max.y, room.max.z};
        const double s0 = glm::dot(lo, f.s_axis);
        const double s1 = glm::dot(hi, f.s_axis);
        f.outline = math::rectangle({std::min(s0, s1), room.min.y}, {std::max(s0, s1), room.max.y});
        return f;
    }
    const Wall w = wall(room, face - 2);
    f = side_frame({w.inward.x, 0.0, w.inward.y}, {w.a.x, 0.0, w.a.y});
    const double length = glm::dot(glm::dvec3(w.b.x - w.a.x, 0.0, w.b.y - w.a.y), f.s_axis);
    f.outline = math::rectangle({std::min(0.0, length), room.min.y}, {std::max(0.0, length), room.max.y});
    return f;
}

glm::dvec2 to_face(const FaceFrame& frame, const glm::dvec3& p) {
    const glm::dvec3 d = p - frame.origin;
    return {glm::dot(d, frame.s_axis), glm::dot(d, frame.t_axis)};
}

glm::dvec3 from_face(const FaceFrame& frame, const glm::dvec2& st) {
    return frame.origin + st.x * frame.s_axis + st.y * frame.t_axis;
}

glm::dvec2 wall_uv(const Room& room, int wall_index, const glm::dvec3& p, double size) {
    const FaceFrame f = face_frame(room, 2 + wall_index);
    const glm::dvec2 st = to_face(f, p);
    return glm::dvec2(st.x, -p.y) / size;
}

bool room_contains(const Room& room, const glm::dvec3& p, double tolerance) {
    if (!(p.y >= room.min.y - tolerance && p.y <= room.max.y + tolerance)) return false;
    if (!is_prism(room)) {
        return p.x >= room.min.x - tolerance && p.x <= room.max.x + tolerance && p.z >= room.min.z - tolerance &&
               p.z <= room.max.z + tolerance;
    }
    return math::contains(room.floor, {p.x, p.z}, tolerance);
}

double floor_area(const Room& room) {
    if (!is_prism(room)) return (room.max.x - room.min.x) * (room.max.z - room.min.z);
    return math::area(room.floor);
}

}  // namespace impossible::layout
