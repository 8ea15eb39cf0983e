// Layouts built in code for the light image tests (lighting set in code, no
// loader involved), and helpers to compare paths.
#pragma once

#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "layout/layout.hpp"
#include "lights/light_images.hpp"
#include "links/portal_links.hpp"

namespace impossible::lights::testing {

inline int add_room(layout::Layout& l, const std::string& id, glm::dvec3 min, glm::dvec3 max) {
    layout::Room r;
    r.id = id;
    r.min = min;
    r.max = max;
    r.face_color.fill(glm::dvec3(0.8));
    l.rooms.push_back(r);
    return static_cast<int>(l.rooms.size()) - 1;
}

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

inline int add_portal(layout::Layout& l, const std::string& id, int room, const math::PortalRect& rect,
                      layout::PortalKind kind = layout::PortalKind::Door, int hole_face = -1) {
    layout::Portal p{id, room, rect};
    p.kind = kind;
    p.hole_face = hole_face;
    l.portals.push_back(p);
    return static_cast<int>(l.portals.size()) - 1;
}

// Portals a and b linked to each other (b is a + 1).
inline int add_pair(layout::Layout& l, const std::string& id_a, int ra, const math::PortalRect& a, int face_a,
                    const std::string& id_b, int rb, const math::PortalRect& b, int face_b,
                    layout::PortalKind kind = layout::PortalKind::Door) {
    const int ia = add_portal(l, id_a, ra, a, kind, face_a);
    add_portal(l, id_b, rb, b, kind, face_b);
    l.portals[static_cast<std::size_t>(ia)].target = ia + 1;
    l.portals[static_cast<std::size_t>(ia) + 1].target = ia;
    return ia;
}

inline void add_light(layout::Layout& l, int room, glm::dvec3 position, double range = 0.0) {
    layout::Light light;
    light.position = position;
    light.range = range;
    l.rooms[static_cast<std::size_t>(room)].lights.push_back(light);
}

inline layout::Layout lit_layout(const std::string& name) {
    layout::Layout l;
    l.source = "<" + name + ">";
    l.name = name;
    l.lighting = layout::Lighting::Lights;
    return l;
}

constexpr int kPosX = static_cast<int>(layout::Face::PosX);
constexpr int kNegX = static_cast<int>(layout::Face::NegX);
constexpr int kPosZ = static_cast<int>(layout::Face::PosZ);
constexpr int kNegZ = static_cast<int>(layout::Face::NegZ);

// "hall" (x -2..2) and "annex" (x 2..6) with a coincident door in the
// wall between them at x = 2 (M = identity); portal 0 is the hall's.
inline layout::Layout doorway() {
    layout::Layout l = lit_layout("doorway");
    const int hall = add_room(l, "hall", {-2, 0, -2}, {2, 3, 2});
    const int annex = add_room(l, "annex", {2, 0, -2}, {6, 3, 2});
    add_pair(l, "hall_east", hall, make_rect({2, 1.1, 0}, {-1, 0, 0}, 1.0, 2.2), kPosX, "annex_west", annex,
             make_rect({2, 1.1, 0}, {1, 0, 0}, 1.0, 2.2), kNegX);
    l.start = {hall, {0, 1.6, 1}, 0.0};
    return l;
}

// The hall's +x door leads to the -z wall of an annex far away (x 10..14):
// the hall's +x becomes the annex's +z.
inline layout::Layout turned_door() {
    layout::Layout l = lit_layout("turned door");
    const int hall = add_room(l, "hall", {-2, 0, -2}, {2, 3, 2});
    const int annex = add_room(l, "annex", {10, 0, -2}, {14, 3, 2});
    add_pair(l, "hall_east", hall, make_rect({2, 1.1, 0}, {-1, 0, 0}, 1.0, 2.2), kPosX, "annex_north", annex,
             make_rect({12, 1.1, -2}, {0, 0, 1}, 1.0, 2.2), kNegZ);
    l.start = {hall, {0, 1.6, 1}, 0.0};
    return l;
}

// The sequence of (portal, branch) of a path, with its light: what makes
// two paths the same path.
struct PathKey {
    int light_room = -1;
    int light = -1;
    std::vector<std::pair<int, bool>> portals;
    bool operator==(const PathKey&) const = default;
};

inline PathKey path_key(const LightImage& image) {
    PathKey key{image.light_room, image.light, {}};
    for (const Aperture& a : image.apertures) key.portals.emplace_back(a.portal, a.reflect);
    return key;
}

inline bool has_path(const RoomLights& room, const PathKey& key) {
    for (const LightImage& image : room.images) {
        if (path_key(image) == key) return true;
    }
    return false;
}

}  // namespace impossible::lights::testing
