// Room faces: inward winding, colours, exact holes, and no T-junctions.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/scene.hpp"
#include "scene_test_helpers.hpp"

namespace impossible::scene::test {
namespace {

// The face an inward normal belongs to (layout::Face order).
int face_of(const glm::dvec3& n) {
    if (n.y > 0.5) return 0;
    if (n.y < -0.5) return 1;
    if (n.x > 0.5) return 2;
    if (n.x < -0.5) return 3;
    if (n.z > 0.5) return 4;
    return 5;
}

// Every triangle: non-empty, wound so that its geometric normal is the stored
// normal, which points into the room; on the room's surface; face colour and
// the room's checker; faces in layout::Face order.
void expect_inward_faces(const layout::Room& room, const std::vector<Triangle>& ts) {
    const glm::dvec3 centre = 0.5 * (room.min + room.max);
    int previous_face = 0;
    for (const Triangle& t : ts) {
        ASSERT_GT(t.area(), 0.0);
        const glm::dvec3 g = t.geometric_normal();
        const int face = face_of(g);
        EXPECT_GE(face, previous_face) << "faces out of layout::Face order";
        previous_face = face;
        for (const Vertex* v : t.v) {
            const glm::dvec3 n(v->normal);
            EXPECT_NEAR(glm::length(n - g), 0.0, 1e-6);
            EXPECT_GT(glm::dot(n, centre - t.centroid()), 0.0);
            EXPECT_EQ(v->color, glm::vec3(room.face_color[static_cast<std::size_t>(face)]));
            EXPECT_EQ(v->checker, static_cast<float>(room.checker));
            const glm::dvec3 p(v->position);
            const double on_surface =
                std::min({std::abs(p.x - room.min.x), std::abs(p.x - room.max.x), std::abs(p.y - room.min.y),
                          std::abs(p.y - room.max.y), std::abs(p.z - room.min.z), std::abs(p.z - room.max.z)});
            EXPECT_LT(on_surface, 1e-6);
        }
    }
}

// Room faces plus the fronts of the given portals (their holes' fillings).
std::vector<Triangle> walls_and_fronts(const Scene& s, const std::vector<int>& portals) {
    std::vector<Triangle> ts = triangles(s, s.cells[0]);
    for (const int p : portals) ts = concat(ts, triangles(s, s.portals[static_cast<std::size_t>(p)].front));
    return ts;
}

bool any_covers(const std::vector<Triangle>& ts, const glm::dvec3& q) {
    for (const Triangle& t : ts) {
        if (covers(t, q)) return true;
    }
    return false;
}

constexpr double kRoomArea = 2 * 16.0 + 4 * 12.0;  // 4 × 3 × 4

// What every room with holes shows: `count` triangles covering its faces
// less `hole_area`, facing inward, closed by the fronts of `portals`.
void expect_holed_room(const Scene& s, const layout::Room& room, std::size_t count, double hole_area,
                       const std::vector<int>& portals) {
    const auto ts = triangles(s, s.cells[0]);
    EXPECT_EQ(ts.size(), count);
    EXPECT_DOUBLE_EQ(total_area(ts), kRoomArea - hole_area);
    expect_inward_faces(room, ts);
    EXPECT_TRUE(closed_and_consistent(walls_and_fronts(s, portals)));
}

TEST(RoomMesh, PlainRoomIsTwelveInwardTriangles) {
    layout::Layout l = one_room_layout();
    l.rooms[0].checker = 0.5;
    const Scene s = build_scene(l);
    ASSERT_EQ(s.cells.size(), 1u);
    const auto ts = triangles(s, s.cells[0]);
    EXPECT_EQ(ts.size(), 12u);
    EXPECT_DOUBLE_EQ(total_area(ts), kRoomArea);
    expect_inward_faces(l.rooms[0], ts);
    EXPECT_TRUE(closed_and_consistent(ts));
}

TEST(RoomMesh, EveryFaceHasItsOwnColour) {
    layout::Layout l = one_room_layout();
    const Scene s = build_scene(l);
    const auto ts = triangles(s, s.cells[0]);
    ASSERT_EQ(ts.size(), 12u);
    for (std::size_t f = 0; f < layout::kFaceCount; ++f) {  // two triangles per face, in order
        for (std::size_t k = 0; k < 2; ++k) {
            EXPECT_EQ(face_of(ts[2 * f + k].geometric_normal()), static_cast<int>(f));
            EXPECT_EQ(ts[2 * f + k].v[0]->color, glm::vec3(l.rooms[0].face_color[f]));
        }
    }
}

// A door in the -z wall, standing on the floor: x in [-0.5, 0.5], y in [0, 2].
layout::Portal door(double x = 0.0, double width = 1.0) {
    return in_face(make_portal("p0", 0, {x, 1.0, -2.0}, {0, 0, 1}, width, 2.0, {0, 1, 0}), layout::Face::NegZ);
}

TEST(RoomMesh, DoorHoleIsExact) {
    layout::Layout l = one_room_layout();
    l.portals.push_back(door());
    const Scene s = build_scene(l);
    const auto ts = triangles(s, s.cells[0]);
    // Lines x: -2 -0.5 0.5 2, y: 0 2 3, z: -2 2. Floor and ceiling 3 cells,
    // ±x walls 2, -z wall 6 - 1 (the hole), +z wall 6: 21 cells.
    EXPECT_EQ(ts.size(), 42u);
    EXPECT_DOUBLE_EQ(total_area(ts), kRoomArea - 2.0);
    expect_inward_faces(l.rooms[0], ts);
    EXPECT_FALSE(any_covers(ts, l.portals[0].rect.center));
    EXPECT_FALSE(any_covers(ts, {0.49, 0.01, -2.0}));
    EXPECT_TRUE(any_covers(ts, {0.51, 0.01, -2.0}));
    // Wall and door front close the room, edge to edge.
    EXPECT_TRUE(closed_and_consistent(walls_and_fronts(s, {0})));
}

TEST(RoomMesh, WindowHoleInTheMiddleOfAWall) {
    layout::Layout l = one_room_layout();
    // In the +x wall: r = up × normal = +z; z in [-0.5, 0.5], y in [1, 2].
    l.portals.push_back(
        in_face(make_portal("p0", 0, {2.0, 1.5, 0.0}, {-1, 0, 0}, 1.0, 1.0, {0, 1, 0}), layout::Face::PosX));
    const Scene s = build_scene(l);
    // Lines x: -2 2, y: 0 1 2 3, z: -2 -0.5 0.5 2. Floor, ceiling, ±z: 3 cells
    // each; -x wall 9, +x wall 8.
    expect_holed_room(s, l.rooms[0], 2u * (4 * 3 + 9 + 8), 1.0, {0});
    EXPECT_FALSE(any_covers(triangles(s, s.cells[0]), l.portals[0].rect.center));
}

TEST(RoomMesh, TwoHolesInOneWall) {
    layout::Layout l = one_room_layout();
    l.portals.push_back(door(-1.0));  // x in [-1.5, -0.5], y in [0, 2]
    l.portals.push_back(
        in_face(make_portal("p0", 0, {1.0, 1.375, -2.0}, {0, 0, 1}, 1.0, 0.75, {0, 1, 0}), layout::Face::NegZ));
    const Scene s = build_scene(l);
    const auto ts = triangles(s, s.cells[0]);
    // Lines x: -2 -1.5 -0.5 0.5 1.5 2 (5 cells), y: 0 1 1.75 2 3 (4), z: 1.
    // -z wall 20 - 3 - 1 = 16 cells, floor and ceiling 5, ±x 4, +z 20.
    EXPECT_EQ(ts.size(), 2u * (16 + 5 + 5 + 4 + 4 + 20));
    EXPECT_DOUBLE_EQ(total_area(ts), kRoomArea - 2.0 - 0.75);
    expect_inward_faces(l.rooms[0], ts);
    EXPECT_FALSE(any_covers(ts, l.portals[0].rect.center));
    EXPECT_FALSE(any_covers(ts, l.portals[1].rect.center));
    EXPECT_TRUE(any_covers(ts, {0.0, 1.5, -2.0}));  // between the two
    // The window's lines cut the door's sides: the door front takes the same
    // points (3 cells), and its side faces too, so nothing has a T-junction.
    EXPECT_EQ(s.portals[0].front.count, 3u * 6);
    EXPECT_TRUE(closed_and_consistent(walls_and_fronts(s, {0, 1})));
    // Its sides are fans over the same points: 2 + 4 + 2 + 4, and the back 2.
    EXPECT_EQ(s.portals[0].inner.count, 14u * 3);
    EXPECT_TRUE(closed_undirected(concat(triangles(s, s.portals[0].front), triangles(s, s.portals[0].inner))));
}

TEST(RoomMesh, TrapdoorInTheCeiling) {
    layout::Layout l = one_room_layout();
    l.portals.push_back(
        in_face(make_portal("p0", 0, {0.0, 3.0, 0.0}, {0, -1, 0}, 1.0, 1.0, {0, 0, 1}), layout::Face::Ceiling));
    const Scene s = build_scene(l);
    // Lines x: 3 cells, y: 1, z: 3. Floor 9, ceiling 8, the walls 3 each.
    expect_holed_room(s, l.rooms[0], 2u * (9 + 8 + 4 * 3), 1.0, {0});
    EXPECT_FALSE(any_covers(triangles(s, s.cells[0]), l.portals[0].rect.center));
}

TEST(RoomMesh, HolesInTwoWalls) {
    layout::Layout l = one_room_layout();
    l.portals.push_back(door());
    l.portals.push_back(
        in_face(make_portal("p0", 0, {2.0, 1.5, 0.0}, {-1, 0, 0}, 1.0, 1.0, {0, 1, 0}), layout::Face::PosX));
    const Scene s = build_scene(l);
    // Lines x: 3 cells, y: 0 1 2 3 (3), z: 3. Floor, ceiling, -x, +z: 9 cells;
    // +x 8; -z 9 - 2 (the door spans two rows).
    expect_holed_room(s, l.rooms[0], 2u * (4 * 9 + 8 + 7), 3.0, {0, 1});
}

TEST(RoomMesh, RotatedRectangleMakesTheSameHole) {
    layout::Layout l = one_room_layout();
    // up = +x, so right = up × normal = -y: width runs along y, height along x.
    l.portals.push_back(
        in_face(make_portal("p0", 0, {0.0, 1.0, -2.0}, {0, 0, 1}, 2.0, 1.0, {1, 0, 0}), layout::Face::NegZ));
    const Scene s = build_scene(l);
    expect_holed_room(s, l.rooms[0], 42u, 2.0, {0});
    EXPECT_FALSE(any_covers(triangles(s, s.cells[0]), l.portals[0].rect.center));
}

TEST(RoomMesh, HoleFillingAWholeWallLeavesItEmpty) {
    layout::Layout l = one_room_layout();
    l.portals.push_back(
        in_face(make_portal("p0", 0, {-2.0, 1.5, 0.0}, {1, 0, 0}, 4.0, 3.0, {0, 1, 0}), layout::Face::NegX));
    const Scene s = build_scene(l);
    expect_holed_room(s, l.rooms[0], 10u, 12.0, {0});
}

TEST(RoomMesh, RectangleSlightlyOffThePlaneIsStillAHole) {
    layout::Layout l = one_room_layout();
    layout::Portal p = door();
    p.rect.center.z += 5e-5;  // within the spec's 1e-4
    l.portals.push_back(p);
    const Scene s = build_scene(l);
    expect_holed_room(s, l.rooms[0], 42u, 2.0, {0});
}

TEST(RoomMesh, PortalsStandingFreeLeaveTheRoomWhole) {
    layout::Layout l = one_room_layout();
    l.rooms.push_back(make_room("other", {-2, 0, -6}, {2, 3, -2}));
    l.portals.push_back(make_portal("p0", 0, {0, 1, 0}, {0, 0, 1}, 1, 2, {0, 1, 0}));  // mid-room
    layout::Portal out = door();
    out.rect.normal = {0, 0, -1};  // in the wall's plane but facing out of room 0:
    out.hole_face = -1;            // the loader makes it stand free
    l.portals.push_back(out);
    l.portals.push_back(door());  // a hole in room 0's -z wall, not in room 1's +z wall
    l.portals.back().room = 0;
    const Scene s = build_scene(l);
    EXPECT_EQ(s.cells[0].count, 42u * 3);
    EXPECT_EQ(s.cells[1].count, 12u * 3);
    for (std::size_t p = 0; p < 2; ++p) {
        EXPECT_EQ(s.portals[p].front.count, 2u * 3);
        EXPECT_EQ(s.portals[p].inner.count, 10u * 3);
    }
}

TEST(RoomMesh, LoadedLayoutCutsTheLoadersHoles) {
    const std::string text = R"({
      "format": "impossible-layout", "version": 1,
      "start": { "room": "a", "position": [0, 1.6, 0] },
      "rooms": [ { "id": "a", "min": [-2, 0, -2], "max": [2, 3, 2] },
                 { "id": "b", "min": [-2, 0, -6], "max": [2, 3, -2] } ],
      "portals": [
        { "id": "ab", "room": "a", "center": [0, 1, -2], "normal": [0, 0, 1],
          "width": 1, "height": 2, "target": "ba" },
        { "id": "ba", "room": "b", "center": [0, 1, -2], "normal": [0, 0, -1],
          "width": 1, "height": 2, "target": "ab" } ] })";
    const layout::LoadResult loaded = layout::load_layout_text(text, "<test>", ".");
    ASSERT_TRUE(loaded.layout) << (loaded.errors.empty() ? "" : loaded.errors[0].str());
    const layout::Layout& l = *loaded.layout;
    const Scene s = build_scene(l);
    for (std::size_t r = 0; r < 2; ++r) {
        const auto ts = triangles(s, s.cells[r]);
        EXPECT_EQ(ts.size(), 42u);  // as DoorHoleIsExact
        EXPECT_DOUBLE_EQ(total_area(ts), kRoomArea - 2.0);
        expect_inward_faces(l.rooms[r], ts);
        EXPECT_FALSE(any_covers(ts, l.portals[r].rect.center));
        EXPECT_TRUE(closed_and_consistent(concat(ts, triangles(s, s.portals[r].front))));
    }
}

TEST(RoomMesh, TiltedHoleFallsBackToExactSlabs) {
    layout::Layout l = one_room_layout();
    // A unit square turned 45° in the +z wall.
    const double h = std::sqrt(0.5);
    l.portals.push_back(
        in_face(make_portal("p0", 0, {0.0, 1.5, 2.0}, {0, 0, -1}, 1.0, 1.0, {h, h, 0}), layout::Face::PosZ));
    const Scene s = build_scene(l);
    const auto ts = triangles(s, s.cells[0]);
    EXPECT_NEAR(total_area(ts), kRoomArea - 1.0, 1e-5);
    expect_inward_faces(l.rooms[0], ts);
    EXPECT_FALSE(any_covers(ts, l.portals[0].rect.center));
    EXPECT_TRUE(any_covers(ts, {0.0, 2.25, 2.0}));  // just above the top corner (y 2.207)
    // The wall's hole corners are the portal front's corners.
    const auto front = triangles(s, s.portals[0].front);
    EXPECT_EQ(front.size(), 2u);
    const auto edges = directed_edges(ts);
    for (const Triangle& t : front) {
        for (const Vertex* v : t.v) {
            bool found = false;
            for (const auto& [e, count] : edges) found = found || e.first == key(v->position);
            EXPECT_TRUE(found);
        }
    }
}

}  // namespace
}  // namespace impossible::scene::test
