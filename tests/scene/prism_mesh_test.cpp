// Prism rooms' faces (scene/prism_mesh.hpp): every face on its plane and in
// its outline, facing into the room with its exact normal, the areas of the
// faces less their holes, and walls, floor, ceiling and portal fronts closing
// the room vertex to vertex (no T-junction), for an L-shaped room, a turned
// room, a curved corridor, trapdoors and a door tilted in its wall.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "layout/room_shape.hpp"
#include "math/polygon.hpp"
#include "scene/scene.hpp"
#include "scene_test_helpers.hpp"
#include "shading/shading.hpp"

namespace impossible::scene::test {
namespace {

using impossible::test::prism_room;

// An L: a 6 × 6 square less its 3 × 3 corner at +x +z, floor 0, ceiling 2.5.
const std::vector<glm::dvec2> kPrismL = {{0, 0}, {6, 0}, {6, 3}, {3, 3}, {3, 6}, {0, 6}};

layout::Layout prism_layout(layout::Room room) {
    layout::Layout l;
    l.source = "<test>";
    l.rooms.push_back(std::move(room));
    l.start.room = 0;
    return l;
}

// A portal in wall `i` of room 0 (hole_face set as the loader does), its
// centre `along` of the way from corner i to i + 1, `bottom` above the floor.
layout::Portal prism_door(const layout::Layout& l, int i, double along, double width, double height,
                          double bottom = 0.0) {
    const layout::Room& room = l.rooms[0];
    const layout::Wall w = layout::wall(room, i);
    const glm::dvec2 c = w.a + along * (w.b - w.a);
    layout::Portal p = make_portal("d" + std::to_string(i), 0, {c.x, room.min.y + bottom + 0.5 * height, c.y},
                                   {w.inward.x, 0.0, w.inward.y}, width, height);
    p.hole_face = 2 + i;
    return p;
}

double prism_perimeter(const layout::Room& room) {
    double sum = 0.0;
    for (int i = 0; i < layout::wall_count(room); ++i) {
        const layout::Wall w = layout::wall(room, i);
        sum += glm::length(w.b - w.a);
    }
    return sum;
}

double prism_surface(const layout::Room& room) {
    return 2.0 * layout::floor_area(room) + prism_perimeter(room) * (room.max.y - room.min.y);
}

double prism_longest_edge(const Triangle& t) {
    return std::max({glm::length(t.p(1) - t.p(0)), glm::length(t.p(2) - t.p(1)), glm::length(t.p(0) - t.p(2))});
}

// No triangle is a sliver (three corners on a line): one beside a long
// triangle would be a crack once a rasteriser snaps its vertices.
void expect_no_slivers(const std::vector<Triangle>& ts) {
    for (const Triangle& t : ts) EXPECT_GT(2.0 * t.area(), 1e-6 * prism_longest_edge(t) * prism_longest_edge(t));
}

// Float vertices: areas agree to a relative 1e-7.
void expect_prism_area(const std::vector<Triangle>& ts, double expected) {
    EXPECT_NEAR(total_area(ts), expected, 1e-7 * expected);
}

// Every triangle of face f (its range, `ranges` from the cell in face order):
// on the face's plane, within its outline, its stored normal the face's
// exact inward normal, and wound to face it.
void expect_prism_faces(const Scene& s, const layout::Room& room) {
    const auto all = triangles(s, s.cells[0]);
    std::size_t seen = 0;
    const math::Polygon2 floor = layout::floor_outline(room);
    for (int f = 0; f < layout::face_count(room); ++f) {
        const layout::FaceFrame frame = layout::face_frame(room, f);
        // The cell's batches run face after face: count this face's triangles
        // by their plane.
        for (; seen < all.size(); ++seen) {
            const Triangle& t = all[seen];
            if (std::abs(glm::dot(t.p(0) + s.origins[0].origin - frame.origin, frame.normal)) > 1e-5 ||
                glm::length(glm::dvec3(t.v[0]->normal) - frame.normal) > 1e-6)
                break;
            // The tessellator may join three collinear points of an edge: a
            // triangle of zero area, whose float corners may face either way.
            if (t.area() > 1e-5 * prism_longest_edge(t)) {
                EXPECT_GT(glm::dot(t.geometric_normal(), frame.normal), 1.0 - 1e-9) << "face " << f;
            }
            for (const Vertex* v : t.v) {
                const glm::dvec3 p = glm::dvec3(v->position) + s.origins[0].origin;
                EXPECT_LT(std::abs(glm::dot(p - frame.origin, frame.normal)), 1e-5) << "face " << f;
                EXPECT_LT(glm::length(glm::dvec3(v->normal) - frame.normal), 1e-6);
                EXPECT_EQ(v->color, glm::vec3(room.face_color[static_cast<std::size_t>(f)]));
                EXPECT_TRUE(math::contains(floor, {p.x, p.z}, 1e-5)) << "face " << f;
                EXPECT_GE(p.y, room.min.y - 1e-6);
                EXPECT_LE(p.y, room.max.y + 1e-6);
            }
        }
    }
    EXPECT_EQ(seen, all.size()) << "triangles out of face order or off their face";
}

// Whether a triangle of ts covers the layout point q (the cell's vertices
// are relative to its origin).
bool prism_covers(const Scene& s, const std::vector<Triangle>& ts, const glm::dvec3& q) {
    for (const Triangle& t : ts)  // (covers() takes a triangle of no area for one that covers everything)
        if (t.area() > 1e-12 && covers(t, q - s.origins[0].origin)) return true;
    return false;
}

std::vector<Triangle> prism_closed(const Scene& s, const std::vector<int>& portals) {
    std::vector<Triangle> ts = triangles(s, s.cells[0]);
    expect_no_slivers(ts);
    for (const int p : portals) ts = concat(ts, triangles(s, s.portals[static_cast<std::size_t>(p)].front));
    return ts;
}

TEST(PrismMesh, LShapedRoomIsClosedAndExact) {
    const layout::Layout l = prism_layout(prism_room("l", kPrismL, 0.0, 2.5));
    const Scene s = build_scene(l);
    const auto ts = triangles(s, s.cells[0]);
    expect_prism_area(ts, prism_surface(l.rooms[0]));
    EXPECT_NEAR(prism_surface(l.rooms[0]), 2 * 27.0 + 24.0 * 2.5, 1e-12);
    expect_prism_faces(s, l.rooms[0]);
    EXPECT_TRUE(closed_and_consistent(prism_closed(s, {})));
    // The reflex corner's floor is not covered: (4.5, 0, 4.5) is outside.
    EXPECT_FALSE(prism_covers(s, ts, {4.5, 0.0, 4.5}));
    EXPECT_TRUE(prism_covers(s, ts, {1.5, 0.0, 4.5}));
}

TEST(PrismMesh, ClockwiseFloorGivesTheSameRoom) {
    std::vector<glm::dvec2> cw(kPrismL.rbegin(), kPrismL.rend());
    const layout::Layout l = prism_layout(prism_room("l", cw, 0.0, 2.5));
    const Scene s = build_scene(l);
    expect_prism_area(triangles(s, s.cells[0]), prism_surface(l.rooms[0]));
    expect_prism_faces(s, l.rooms[0]);
    EXPECT_TRUE(closed_and_consistent(prism_closed(s, {})));
}

TEST(PrismMesh, DoorsInTheWallsOfATurnedRoom) {
    // A 5 × 4 rectangle turned 30 degrees, 1 km from the origin (local
    // coordinates), with a door standing on the floor and a window.
    const double c = std::cos(0.5235987755982988), sn = std::sin(0.5235987755982988);
    std::vector<glm::dvec2> floor;
    for (const glm::dvec2 p : {glm::dvec2(0, 0), glm::dvec2(5, 0), glm::dvec2(5, 4), glm::dvec2(0, 4)})
        floor.push_back(glm::dvec2(1000.0 + c * p.x - sn * p.y, -700.0 + sn * p.x + c * p.y));
    layout::Layout l = prism_layout(prism_room("turned", floor, 10.0, 13.0));
    l.portals.push_back(prism_door(l, 0, 0.5, 1.0, 2.0));
    l.portals.push_back(prism_door(l, 1, 0.25, 0.8, 0.6, 1.2));
    const Scene s = build_scene(l);
    const auto ts = triangles(s, s.cells[0]);
    expect_prism_area(ts, prism_surface(l.rooms[0]) - 2.0 - 0.48);
    expect_prism_faces(s, l.rooms[0]);
    EXPECT_TRUE(closed_and_consistent(prism_closed(s, {0, 1})));
    EXPECT_FALSE(prism_covers(s, ts, l.portals[0].rect.center));
    EXPECT_FALSE(prism_covers(s, ts, l.portals[1].rect.center));
    // The window's heights cut every wall, the door's sides and its front.
    EXPECT_GT(s.portals[0].front.count, 6u);
    EXPECT_TRUE(closed_undirected(concat(triangles(s, s.portals[0].front), triangles(s, s.portals[0].inner))));
}

TEST(PrismMesh, CurvedCorridorIsClosed) {
    // A quarter ring, radii 4 and 6, 12 walls on each side.
    std::vector<glm::dvec2> floor;
    const int n = 12;
    for (int k = 0; k <= n; ++k) {
        const double a = 1.5707963267948966 * k / n;
        floor.push_back({6.0 * std::cos(a), 6.0 * std::sin(a)});
    }
    for (int k = n; k >= 0; --k) {
        const double a = 1.5707963267948966 * k / n;
        floor.push_back({4.0 * std::cos(a), 4.0 * std::sin(a)});
    }
    layout::Layout l = prism_layout(prism_room("arc", floor, 0.0, 2.4));
    l.portals.push_back(prism_door(l, n, 0.5, 1.0, 2.0));  // the end wall at angle 90 degrees
    const Scene s = build_scene(l);
    expect_prism_area(triangles(s, s.cells[0]), prism_surface(l.rooms[0]) - 2.0);
    expect_prism_faces(s, l.rooms[0]);
    EXPECT_TRUE(closed_and_consistent(prism_closed(s, {0})));
}

TEST(PrismMesh, TrapdoorsInFloorAndCeiling) {
    layout::Layout l = prism_layout(prism_room("l", kPrismL, 0.0, 2.5));
    // A trapdoor turned 20 degrees in the floor (facing up), one in the
    // ceiling (facing down) in the L's other arm.
    const double a = 0.3490658503988659;
    layout::Portal down = make_portal("down", 0, {1.5, 0.0, 4.5}, {0, 1, 0}, 1.0, 0.8, {std::sin(a), 0, std::cos(a)});
    down.hole_face = 0;
    layout::Portal up = make_portal("up", 0, {4.5, 2.5, 1.5}, {0, -1, 0}, 1.2, 1.0, {0, 0, 1});
    up.hole_face = 1;
    l.portals.push_back(down);
    l.portals.push_back(up);
    const Scene s = build_scene(l);
    const auto ts = triangles(s, s.cells[0]);
    expect_prism_area(ts, prism_surface(l.rooms[0]) - 0.8 - 1.2);
    expect_prism_faces(s, l.rooms[0]);
    EXPECT_TRUE(closed_and_consistent(prism_closed(s, {0, 1})));
    EXPECT_FALSE(prism_covers(s, ts, down.rect.center));
    EXPECT_FALSE(prism_covers(s, ts, up.rect.center));
    EXPECT_TRUE(prism_covers(s, ts, {1.5, 0.0, 5.3}));
}

TEST(PrismMesh, TrapdoorsFlushWithWalls) {
    layout::Layout l = prism_layout(prism_room("l", kPrismL, 0.0, 2.5));
    // One against the wall x = 0 (50 um inside the loader's tolerance
    // beyond it), one in the corner (6, 0) of two walls, in the ceiling.
    layout::Portal down = make_portal("down", 0, {0.5 - 5e-5, 0.0, 4.5}, {0, 1, 0}, 1.0, 1.2, {0, 0, 1});
    down.hole_face = 0;
    layout::Portal up = make_portal("up", 0, {5.4, 2.5, 0.5}, {0, -1, 0}, 1.0, 1.2, {1, 0, 0});
    up.hole_face = 1;
    l.portals.push_back(down);
    l.portals.push_back(up);
    const Scene s = build_scene(l);
    const auto ts = triangles(s, s.cells[0]);
    // The first hole loses its 50 um beyond the wall.
    expect_prism_area(ts, prism_surface(l.rooms[0]) - (1.0 - 5e-5) * 1.2 - 1.2);
    expect_prism_faces(s, l.rooms[0]);
    // The walls take the holes' corners: floor, walls and fronts close.
    EXPECT_TRUE(closed_and_consistent(prism_closed(s, {0, 1})));
    EXPECT_FALSE(prism_covers(s, ts, {0.01, 0.0, 4.5}));
    EXPECT_FALSE(prism_covers(s, ts, {5.99, 2.5, 0.01}));
}

TEST(PrismMesh, WindowsCutOnlyTheirOwnRunOfWalls) {
    // A 60-sided room with windows at 13 different heights: one in every
    // fifth wall, and two side by side in walls 30 and 31 (a run of two).
    std::vector<glm::dvec2> floor;
    for (int k = 0; k < 60; ++k)
        floor.push_back({8.0 * std::cos(0.10471975511965977 * k), 8.0 * std::sin(0.10471975511965977 * k)});
    layout::Layout l = prism_layout(prism_room("round", floor, 0.0, 3.0));
    double holes = 0.0;
    for (int i = 0; i < 60; i += 5) {
        l.portals.push_back(prism_door(l, i, 0.5, 0.4, 0.3, 0.2 + 0.17 * i / 5));
        holes += 0.12;
    }
    l.portals.push_back(prism_door(l, 31, 0.5, 0.4, 0.5, 0.7));
    holes += 0.2;
    for (std::size_t p = 0; p < l.portals.size(); ++p) l.portals[p].id = "w" + std::to_string(p);
    const Scene s = build_scene(l);
    const auto ts = triangles(s, s.cells[0]);
    expect_prism_area(ts, prism_surface(l.rooms[0]) - holes);
    expect_prism_faces(s, l.rooms[0]);
    std::vector<int> all(l.portals.size());
    for (std::size_t p = 0; p < all.size(); ++p) all[p] = static_cast<int>(p);
    EXPECT_TRUE(closed_and_consistent(prism_closed(s, all)));
    // Heights shared room-wide would cut all 60 walls 27 times (over 3,000
    // triangles); each window cuts its own wall, and the pair each other.
    EXPECT_LT(ts.size(), 700u);
}

TEST(PrismMesh, DoorTiltedInItsWallIsTessellated) {
    layout::Layout l = prism_layout(prism_room("l", kPrismL, 0.0, 2.5));
    layout::Portal p = prism_door(l, 1, 0.5, 0.8, 1.0, 0.8);  // wall 1 is x = 6, facing -x
    p.rect.up = glm::normalize(glm::dvec3(0.0, 1.0, 0.3));
    l.portals.push_back(p);
    const Scene s = build_scene(l);
    expect_prism_area(triangles(s, s.cells[0]), prism_surface(l.rooms[0]) - 0.8);
    expect_prism_faces(s, l.rooms[0]);
    EXPECT_TRUE(closed_and_consistent(prism_closed(s, {0})));
    EXPECT_FALSE(prism_covers(s, triangles(s, s.cells[0]), p.rect.center));
}

TEST(PrismMesh, WallTexturesRunAlongTheWall) {
    layout::Room room = prism_room("l", kPrismL, 0.0, 2.5);
    const auto image = std::make_shared<const image::Pixels>(image::Pixels{2, 2, 4, 8, std::vector<std::uint8_t>(16)});
    room.face_texture[3] = image;  // wall 1, x = 6 from z = 0 to 3
    room.texture_size = 0.5;
    const layout::Layout l = prism_layout(room);
    const Scene s = build_scene(l);
    ASSERT_EQ(s.batches[0].size(), 3u);  // untextured, wall 1, untextured
    const auto ts = triangles(s, s.batches[0][1].range);
    ASSERT_EQ(ts.size(), 2u);
    for (const Triangle& t : ts) {
        for (const Vertex* v : t.v) {
            const glm::dvec2 uv = layout::wall_uv(l.rooms[0], 1, glm::dvec3(v->position), 0.5);
            EXPECT_NEAR(v->uv.x, uv.x, 1e-6);
            EXPECT_NEAR(v->uv.y, uv.y, 1e-6);
        }
    }
}

TEST(PrismMesh, WallsNear45DegreesCheckerAlikeInFloatAndDouble) {
    // A rectangle turned 45 degrees about (3.3, -1.7), corners rounded to
    // the micrometre: its walls' normals differ from 45 degrees by an ulp
    // or so in double, which float rounding alone turns into a tie. The
    // vertices keep the wall's normal (in float), and the checker's tie
    // (shading::checker_dark) makes the float and the exact normal choose
    // the same squares.
    const double c = std::cos(0.7853981633974483), sn = std::sin(0.7853981633974483);
    std::vector<glm::dvec2> floor;
    for (const glm::dvec2 p : {glm::dvec2(-2, -2), glm::dvec2(2.5, -2), glm::dvec2(2.5, 2), glm::dvec2(-2, 2)})
        floor.push_back(
            {std::round(1e6 * (3.3 + c * p.x - sn * p.y)) / 1e6, std::round(1e6 * (-1.7 + sn * p.x + c * p.y)) / 1e6});
    const layout::Layout l = prism_layout(prism_room("turned", floor, 0.0, 3.0));
    const Scene s = build_scene(l);
    int near_ties = 0;
    for (int i = 0; i < 4; ++i) {
        const glm::dvec3 n = layout::face_frame(l.rooms[0], 2 + i).normal;
        near_ties +=
            static_cast<float>(std::abs(n.x)) == static_cast<float>(std::abs(n.z)) && std::abs(n.x) != std::abs(n.z);
    }
    EXPECT_GT(near_ties, 0) << "the case this test is about";
    int walls_seen = 0;
    for (const Triangle& t : triangles(s, s.cells[0])) {
        const glm::dvec3 g(t.v[0]->normal);
        if (std::abs(g.y) > 0.5) continue;
        int wall = -1;
        for (int i = 0; i < 4; ++i)
            if (glm::length(layout::face_frame(l.rooms[0], 2 + i).normal - g) < 1e-6) wall = i;
        ASSERT_GE(wall, 0);
        ++walls_seen;
        const layout::FaceFrame frame = layout::face_frame(l.rooms[0], 2 + wall);
        EXPECT_EQ(t.v[0]->normal, glm::vec3(frame.normal)) << "wall " << wall;
        for (int k = 0; k < 64; ++k) {
            const glm::dvec3 p = layout::from_face(frame, {0.07 * k, 0.05 * k});
            EXPECT_EQ(shading::checker_dark(p, g, 0.3), shading::checker_dark(p, frame.normal, 0.3))
                << "wall " << wall << " point " << k;
        }
    }
    EXPECT_GT(walls_seen, 0);
}

}  // namespace
}  // namespace impossible::scene::test
