// Rooms and portals built in code, shared by the test programs (no loader).
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "layout/layout.hpp"

namespace impossible::test {

// A room whose six faces have six different colours (so a test can tell which
// face it sees): face f has colour (0.1 + 0.1·f, tint.y, tint.z).
inline layout::Room make_room(const std::string& id, glm::dvec3 min, glm::dvec3 max,
                              glm::dvec3 tint = {0.0, 0.5, 0.9}) {
    layout::Room room;
    room.id = id;
    room.min = min;
    room.max = max;
    for (int f = 0; f < layout::kFaceCount; ++f) room.face_color[f] = glm::dvec3(0.1 + 0.1 * f, tint.y, tint.z);
    return room;
}

// A grey room (every face 0.8) appended to `l`; returns its index.
inline int add_room(layout::Layout& l, const std::string& id, glm::dvec3 min, glm::dvec3 max) {
    layout::Room r;
    r.id = id;
    r.min = min;
    r.max = max;
    std::fill(r.face_color.begin(), r.face_color.end(), glm::dvec3(0.8));
    l.rooms.push_back(r);
    return static_cast<int>(l.rooms.size()) - 1;
}

// A prism room (layout-format.md, "Rooms of any shape") over the floor
// polygon `floor` ([x, z], either winding) from y0 to y1: face f has colour
// (0.1 + 0.05·f mod 1, tint.y, tint.z), so a test can tell the faces apart.
inline layout::Room prism_room(const std::string& id, std::vector<glm::dvec2> floor, double y0, double y1,
                               glm::dvec3 tint = {0.0, 0.5, 0.9}) {
    layout::Room room;
    room.id = id;
    room.min = {floor.front().x, y0, floor.front().y};
    room.max = room.min;
    for (const glm::dvec2& c : floor) {
        room.min = glm::min(room.min, glm::dvec3(c.x, y0, c.y));
        room.max = glm::max(room.max, glm::dvec3(c.x, y1, c.y));
    }
    room.max.y = y1;
    const std::size_t faces = 2 + floor.size();
    room.floor = std::move(floor);
    room.face_color.resize(faces);
    room.face_texture.resize(faces);
    for (std::size_t f = 0; f < faces; ++f) {
        const double x = 0.1 + 0.05 * static_cast<double>(f);
        room.face_color[f] = glm::dvec3(x - static_cast<double>(static_cast<int>(x)), tint.y, tint.z);
    }
    return room;
}

// A portal rectangle with `up` made orthogonal to the (normalised) normal.
inline math::PortalRect make_rect(glm::dvec3 center, glm::dvec3 normal, double width = 1.0, double height = 2.0,
                                  glm::dvec3 up = {0, 1, 0}) {
    math::PortalRect p;
    p.center = center;
    p.normal = glm::normalize(normal);
    p.up = glm::normalize(up - glm::dot(up, p.normal) * p.normal);
    p.width = width;
    p.height = height;
    return p;
}

// A portal of `room` (normal and up unit and orthogonal), target unset.
inline layout::Portal make_portal(const std::string& id, int room, glm::dvec3 center, glm::dvec3 normal,
                                  double width = 1.0, double height = 2.0, glm::dvec3 up = {0.0, 1.0, 0.0},
                                  double depth = 0.25) {
    layout::Portal p;
    p.id = id;
    p.room = room;
    p.rect.center = center;
    p.rect.normal = normal;
    p.rect.up = up;
    p.rect.width = width;
    p.rect.height = height;
    p.rect.depth = depth;
    return p;
}

// A mirror of `room` (layout-format.md, "Mirrors and windows"): no target,
// no depth (0, as the loader sets it). It must lie in a face of its room.
inline layout::Portal make_mirror(const std::string& id, int room, glm::dvec3 center, glm::dvec3 normal,
                                  double width = 1.0, double height = 2.0, glm::dvec3 tint = {1.0, 1.0, 1.0},
                                  glm::dvec3 up = {0.0, 1.0, 0.0}) {
    layout::Portal p = make_portal(id, room, center, normal, width, height, up, 0.0);
    p.kind = layout::PortalKind::Mirror;
    p.tint = tint;
    return p;
}

// A window of `room`, target unset (pair it with add_pair): depth 0, as the
// loader sets it. It must lie in a face of its room.
inline layout::Portal make_window(const std::string& id, int room, glm::dvec3 center, glm::dvec3 normal,
                                  double width = 1.0, double height = 2.0, glm::dvec3 tint = {1.0, 1.0, 1.0},
                                  double reflectance = 0.1, glm::dvec3 up = {0.0, 1.0, 0.0}) {
    layout::Portal p = make_portal(id, room, center, normal, width, height, up, 0.0);
    p.kind = layout::PortalKind::Window;
    p.tint = tint;
    p.reflectance = reflectance;
    return p;
}

// Appends the two portals and names each as the other's target.
inline void add_pair(layout::Layout& l, layout::Portal a, layout::Portal b) {
    const int ia = static_cast<int>(l.portals.size());
    a.target = ia + 1;
    b.target = ia;
    l.portals.push_back(a);
    l.portals.push_back(b);
}

}  // namespace impossible::test
