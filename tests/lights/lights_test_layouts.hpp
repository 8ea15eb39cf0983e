// Layouts built in code for the light image tests (lighting set in code, no
// loader involved), and helpers to compare paths.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "common/layouts.hpp"
#include "layout/layout.hpp"
#include "lights/light_images.hpp"
#include "links/portal_links.hpp"

namespace impossible::lights::testing {

using test::add_room;
using test::make_rect;

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

// "l": an L (6 × 6 less its 3 × 3 corner at +x +z; walls 2 (z = 3) and 3
// (x = 3) meet at the reflex corner (3, 3)), lit by a lamp in each arm; a
// door in wall 2 into box "a" (x 1.5..6, z 3..6, reaching back over the
// L's north arm) and one in wall 3 into box "b" (x 3..6, z 1.5..6, over
// the east arm), each with a lamp; a mirror in wall 5 (x = 0). Portals:
// 0 l→a, 1 a→l, 2 l→b, 3 b→l, 4 the mirror.
inline layout::Layout l_flat() {
    layout::Layout l = lit_layout("l_flat");
    l.rooms.push_back(test::prism_room("l", {{0, 0}, {6, 0}, {6, 3}, {3, 3}, {3, 6}, {0, 6}}, 0.0, 3.0));
    const int a = add_room(l, "a", {1.5, 0, 3}, {6, 2.8, 6});
    const int b = add_room(l, "b", {3, 0, 1.5}, {6, 2.8, 6});
    add_pair(l, "l_a", 0, make_rect({4.5, 1.1, 3}, {0, 0, -1}, 1.0, 2.2), 2 + 2, "a_l", a,
             make_rect({4.5, 1.1, 3}, {0, 0, 1}, 1.0, 2.2), kNegZ);
    add_pair(l, "l_b", 0, make_rect({3, 1.1, 4.5}, {-1, 0, 0}, 1.0, 2.2), 2 + 3, "b_l", b,
             make_rect({3, 1.1, 4.5}, {1, 0, 0}, 1.0, 2.2), kNegX);
    add_portal(l, "mirror", 0, make_rect({0, 1.5, 3}, {1, 0, 0}, 2.0, 2.0), layout::PortalKind::Mirror, 2 + 5);
    add_light(l, 0, {5, 2.5, 1.5});
    add_light(l, 0, {1.5, 2.5, 5});
    add_light(l, a, {2.5, 2.5, 5});
    add_light(l, b, {5, 2.0, 2.5});
    l.start = {0, {1, 1.6, 1}, 0.0};
    return l;
}

// "high" (y 0..3) and "low" (y 0..2) on the same 4 × 4 m floor, joined by
// coincident doors standing free at z = 0 that reach to y = 2.5, above the
// low room's ceiling (the fuzzer's layouts do that; seed 44 case 912): a
// lamp of the high room at y = 2.6 shines through the door's top into the
// low room only where the shadow ray does not leave the low room through
// its ceiling first. Portals: 0 high→low (front +z), 1 low→high.
inline layout::Layout low_ceiling() {
    layout::Layout l = lit_layout("low_ceiling");
    const int high = add_room(l, "high", {-2, 0, -2}, {2, 3, 2});
    const int low = add_room(l, "low", {-2, 0, -2}, {2, 2, 2});
    add_pair(l, "high_low", high, make_rect({0, 1.25, 0}, {0, 0, 1}, 1.5, 2.5), -1, "low_high", low,
             make_rect({0, 1.25, 0}, {0, 0, -1}, 1.5, 2.5), -1);
    add_light(l, high, {0.3, 2.6, 1.2});
    l.start = {high, {0, 1.6, 1}, 0.0};
    return l;
}

// "star": a prism room on a star of `corners` corners, at radii 5 and 4 m in
// turn (corner i at angle 2πi / corners), y 0..3, lit by `lights` lamps on a
// ring of radius 2 m at y = 2 (lamp i at angle 2π(i + 0.5) / lights). Every
// wall can be crossed (corners lie behind its line), and a lamp lies behind
// the planes of about half of them (478 of 1,000).
inline layout::Layout star_room(int corners, int lights) {
    layout::Layout l = lit_layout("star");
    const double pi = 3.14159265358979323846;
    std::vector<glm::dvec2> floor;
    for (int i = 0; i < corners; ++i) {
        const double a = 2.0 * pi * i / corners, r = i % 2 == 0 ? 5.0 : 4.0;
        floor.emplace_back(r * std::cos(a), r * std::sin(a));
    }
    l.rooms.push_back(test::prism_room("star", std::move(floor), 0.0, 3.0));
    for (int i = 0; i < lights; ++i) {
        const double a = 2.0 * pi * (i + 0.5) / lights;
        add_light(l, 0, {2.0 * std::cos(a), 2.0, 2.0 * std::sin(a)});
    }
    l.start = {0, {0, 1.6, 0}, 0.0};
    return l;
}

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

// A portal rectangle on wall `wall` (0: -x, 1: +x, 2: -z, 3: +z) of the
// 4 × 3 × 4 box at x offset `x0`, at a random place, of a random size or
// the size given, inside the wall (so it is a hole in it).
inline std::pair<math::PortalRect, int> random_wall_rect(std::mt19937_64& rng, double x0, int wall, double width = 0.0,
                                                         double height = 0.0) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    if (width <= 0.0) width = 0.3 + unit(rng);
    if (height <= 0.0) height = 0.5 + 1.5 * unit(rng);
    const double along = (unit(rng) - 0.5) * (3.8 - width);
    const double y = 0.05 + height / 2 + unit(rng) * (2.9 - height);
    const glm::dvec3 centers[] = {{x0 - 2, y, along}, {x0 + 2, y, along}, {x0 + along, y, -2}, {x0 + along, y, 2}};
    const glm::dvec3 normals[] = {{1, 0, 0}, {-1, 0, 0}, {0, 0, 1}, {0, 0, -1}};
    const int faces[] = {kNegX, kPosX, kNegZ, kPosZ};
    return {make_rect(centers[wall], normals[wall], width, height), faces[wall]};
}

// Three 4 × 3 × 4 boxes far apart, each with a light at a random place
// (some spots, some with a range). A door from the first to the second and
// a door (or a window pair, tinted) from the second to the third, each
// end on a random wall at a random place (so most turn what passes them),
// a mirror in the second, and a free-standing door pair, turned at random,
// between the second and the first.
inline layout::Layout random_chain(std::mt19937_64& rng, bool window) {
    layout::Layout l = lit_layout("random chain");
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto random_unit = [&] { return glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)) - 0.5); };
    for (int r = 0; r < 3; ++r) {
        const double x0 = 20.0 * r;
        add_room(l, "r" + std::to_string(r), {x0 - 2, 0, -2}, {x0 + 2, 3, 2});
        add_light(l, r, {x0 - 1.8 + 3.6 * unit(rng), 0.2 + 2.6 * unit(rng), -1.8 + 3.6 * unit(rng)},
                  unit(rng) < 0.3 ? 6.0 : 0.0);
        if (unit(rng) < 0.5)
            l.rooms[static_cast<std::size_t>(r)].lights.back().spot = layout::Spot{random_unit(), 10, 60};
    }
    std::array<int, 4> walls{0, 1, 2, 3};
    std::shuffle(walls.begin(), walls.end(), rng);
    const auto [a, fa] = random_wall_rect(rng, 0.0, static_cast<int>(rng() % 4));
    const auto [b, fb] = random_wall_rect(rng, 20.0, walls[0], a.width, a.height);
    add_pair(l, "d1", 0, a, fa, "d1_back", 1, b, fb);
    const auto [m, fm] = random_wall_rect(rng, 20.0, walls[1]);
    add_portal(l, "mirror", 1, m, layout::PortalKind::Mirror, fm);
    const auto [c, fc] = random_wall_rect(rng, 20.0, walls[2]);
    const auto [d, fd] = random_wall_rect(rng, 40.0, static_cast<int>(rng() % 4), c.width, c.height);
    const int w = add_pair(l, "d2", 1, c, fc, "d2_back", 2, d, fd,
                           window ? layout::PortalKind::Window : layout::PortalKind::Door);
    if (window) {
        l.portals[static_cast<std::size_t>(w)].reflectance = 0.3;
        l.portals[static_cast<std::size_t>(w)].tint = glm::dvec3(0.9, 0.8, 0.7);
        l.portals[static_cast<std::size_t>(w) + 1].reflectance = 0.4;
    }
    const glm::dvec3 n1(unit(rng) - 0.5, 0, unit(rng) - 0.5), n2(unit(rng) - 0.5, 0, unit(rng) - 0.5);
    add_pair(l, "free", 1, make_rect({20 + unit(rng) - 0.5, 1.5, unit(rng) - 0.5}, glm::normalize(n1), 0.8, 1.0), -1,
             "free_back", 0, make_rect({unit(rng) - 0.5, 1.5, unit(rng) - 0.5}, glm::normalize(n2), 0.8, 1.0), -1);
    l.start = {0, {0, 1.5, 0}, 0.0};
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
