// Holes in prism rooms' faces in the tracer (layout-format.md, "Rooms of any
// shape" and "The portal box"): a door in a slanted wall, seen and stood in;
// a trapdoor in a floor seen from above and from below; an L's concave
// corner hiding a door behind it and letting it be seen past it; a shadow
// ray stopped by an L's wall; and the same holes as the loader finds.
#include <cmath>

#include <gtest/gtest.h>

#include "trace/prism_test_util.hpp"
#include "trace/trace_test_util.hpp"
#include "trace/tracer.hpp"

namespace impossible::trace {
namespace {

using impossible::test::prism_room;
using test::add_pair;
using test::inward_normal;
using test::l_floor;
using test::make_portal;
using test::turned_square;
using test::wall_point;

// The yaw that looks along the horizontal direction d.
double holes_yaw_along(dvec3 d) { return std::atan2(-d.x, -d.z) * 180.0 / std::numbers::pi; }

// Room 0: a square turned by 30° (half side 2 about the origin, y 0..3) with
// a door 1 m wide, 2.2 m high in the middle of its wall 1; room 1: a box
// [10, 14] × [0, 3] × [-2, 2] whose -x face holds the door's partner.
layout::Layout slanted_door() {
    layout::Layout l;
    l.source = "<test>";
    const std::vector<glm::dvec2> floor = turned_square({0.0, 0.0}, 2.0, 30.0);
    l.rooms.push_back(prism_room("turned", floor, 0.0, 3.0));
    l.rooms.push_back(test::make_room("box", {10, 0, -2}, {14, 3, 2}));
    add_pair(l, make_portal("a", 0, wall_point(floor, 1, 1.1), inward_normal(floor, 1), 1.0, 2.2),
             make_portal("b", 1, {10, 1.1, 0}, {1, 0, 0}, 1.0, 2.2));
    l.start.room = 0;
    return l;
}

TEST(TracerPrismHoles, ADoorInASlantedWallLetsRaysThroughItsHoleOnly) {
    const layout::Layout l = slanted_door();
    const Scene scene = prepare_scene(l).value();
    ASSERT_EQ(scene.rooms[0].prism.faces.size(), 6u);
    EXPECT_EQ(scene.rooms[0].prism.faces[3].surface.holes, std::vector<int>{0});  // wall 1
    EXPECT_TRUE(scene.portals[0].in_hole);
    const std::vector<glm::dvec2> floor = l.rooms[0].floor;
    const dvec3 n = inward_normal(floor, 1);
    const dvec3 along = glm::normalize(wall_point(floor, 1, 0.0, 1.0) - wall_point(floor, 1, 0.0, 0.0));
    const dvec3 centre = wall_point(floor, 1, 1.1);
    const dvec3 eye = centre + 1.5 * n + dvec3(0.2, 0.3, -0.1);
    // Inside the hole (edges included): room 1 beyond.
    for (const dvec3& p : {centre, centre + 0.4999 * along, centre - 0.4999 * along + dvec3(0, 1.0999, 0)}) {
        const TraceHit hit = trace_ray(scene, eye, p - eye, 0, 8);
        EXPECT_EQ(hit.id, 2);
        EXPECT_EQ(hit.portals_passed, 1);
    }
    // Beside it and above it: the wall, with its normal.
    for (const dvec3& p : {centre + 0.5001 * along, centre - 0.5001 * along, centre + dvec3(0, 1.1001, 0)}) {
        const TraceHit hit = trace_ray(scene, eye, p - eye, 0, 8);
        EXPECT_EQ(hit.id, 1);
        test::expect_point(hit.point, p, 1e-12);
        EXPECT_NEAR(glm::length(hit.normal - n), 0.0, 1e-15);
    }
}

TEST(TracerPrismHoles, AnEyeInTheBoxOfADoorInASlantedWall) {
    const layout::Layout l = slanted_door();
    const Scene scene = prepare_scene(l).value();
    const std::vector<glm::dvec2> floor = l.rooms[0].floor;
    const dvec3 n = inward_normal(floor, 1);
    // The head 2 cm in front of the door's plane, in room 0, looking along
    // the wall: one eye is 1.2 cm behind the plane, in the box's column,
    // reached through the door.
    const dvec3 head = wall_point(floor, 1, 1.6) + 0.02 * n;
    const dvec3 along = glm::normalize(glm::cross(n, dvec3(0, 1, 0)));
    TraceDesc desc;
    desc.head = {head, holes_yaw_along(along), 0.0, 0.0};
    desc.room = 0;
    desc.eye_width = 40;
    desc.eye_height = 30;
    const std::array<math::Eye, 2> eyes = math::eyes_of(desc.head, desc.ipd);
    const int crossed = glm::dot(eyes[0].position - head, n) < 0.0 ? 0 : 1;
    ASSERT_LT(glm::dot(eyes[crossed].position - wall_point(floor, 1, 1.6), n), 0.0);
    const image::Image ahead = trace_frame(scene, desc).value();
    // That eye sees room 1 on the box's side face ahead, nothing is empty.
    EXPECT_EQ(test::pixel_id(ahead, crossed * 40 + 20, 15), 2);
    EXPECT_EQ(test::pixel_id(ahead, (1 - crossed) * 40 + 20, 15), 1);
    EXPECT_EQ(test::count_id(ahead, 1) + test::count_id(ahead, 2), 2 * 40 * 30);
}

// Room 0 above (a square turned by 20°, y 2..5) and room 1 below (one turned
// by 45°, y -1..2) share a trapdoor 1 × 1.2 m, itself turned by 20° in the
// floor: coincident rectangles, the transfer the identity.
layout::Layout trapdoor() {
    layout::Layout l;
    l.source = "<test>";
    l.rooms.push_back(prism_room("above", turned_square({0.0, 0.0}, 2.0, 20.0), 2.0, 5.0));
    l.rooms.push_back(prism_room("below", turned_square({0.0, 0.0}, 2.2, 45.0), -1.0, 2.0));
    const double a = 20.0 * std::numbers::pi / 180.0;
    const dvec3 up(std::sin(a), 0.0, -std::cos(a));
    add_pair(l, make_portal("down", 0, {0.3, 2.0, -0.2}, {0, 1, 0}, 1.0, 1.2, up),
             make_portal("up", 1, {0.3, 2.0, -0.2}, {0, -1, 0}, 1.0, 1.2, up));
    l.start.room = 0;
    return l;
}

TEST(TracerPrismHoles, ATrapdoorIsSeenFromAboveAndFromBelow) {
    const layout::Layout l = trapdoor();
    const Scene scene = prepare_scene(l).value();
    EXPECT_EQ(scene.rooms[0].prism.faces[0].surface.holes, std::vector<int>{0});  // the floor above
    EXPECT_EQ(scene.rooms[1].prism.faces[1].surface.holes, std::vector<int>{1});  // the ceiling below
    const dvec3 centre(0.3, 2.0, -0.2);
    const dvec3 right = math::portal_right(l.portals[0].rect), up = l.portals[0].rect.up;
    struct Side {
        int room;
        dvec3 eye;
        int through;  // the id seen through the hole
    };
    for (const Side& side : {Side{0, {0.9, 3.6, 0.7}, 2}, Side{1, {-0.4, 0.3, 0.6}, 1}}) {
        SCOPED_TRACE(side.room == 0 ? "from above" : "from below");
        const dvec3 n(0.0, side.room == 0 ? 1.0 : -1.0, 0.0);
        for (const dvec3& p : {centre, centre + 0.4999 * right + 0.5999 * up, centre - 0.4999 * right - 0.5999 * up}) {
            const TraceHit hit = trace_ray(scene, side.eye, p - side.eye, side.room, 8);
            EXPECT_EQ(hit.id, side.through);
            EXPECT_EQ(hit.portals_passed, 1);
        }
        // Past the turned rectangle's edges (inside its axis-aligned bounds).
        for (const dvec3& p : {centre + 0.5001 * right, centre - 0.6001 * up, centre + 0.45 * right + 0.62 * up}) {
            const TraceHit hit = trace_ray(scene, side.eye, p - side.eye, side.room, 8);
            EXPECT_EQ(hit.id, side.room + 1);
            test::expect_point(hit.point, p, 1e-12);
            EXPECT_EQ(hit.normal, n);
        }
        // A whole frame looking at the trapdoor: both rooms, nothing empty.
        TraceDesc desc;
        desc.head = {side.eye, 0.0, side.room == 0 ? -60.0 : 60.0, 0.0};
        desc.room = side.room;
        desc.eye_width = 40;
        desc.eye_height = 30;
        const image::Image image = trace_frame(scene, desc).value();
        EXPECT_GT(test::count_id(image, side.through), 0);
        EXPECT_EQ(test::count_id(image, 1) + test::count_id(image, 2), 2 * 40 * 30);
    }
}

// Room 0: the L of prism_test_util.hpp (y 0..3) with a door 1 m wide in
// wall 3 (x = 2, z 2 → 4, beside the concave corner (2, 2)), to a box room
// [10, 14] × [0, 3] × [1, 5] whose +x face holds the partner.
layout::Layout l_with_door() {
    layout::Layout l;
    l.source = "<test>";
    l.rooms.push_back(prism_room("ell", l_floor(), 0.0, 3.0));
    l.rooms.push_back(test::make_room("box", {10, 0, 1}, {14, 3, 5}));
    add_pair(l, make_portal("a", 0, {2, 1.1, 3}, {-1, 0, 0}, 1.0, 2.2),
             make_portal("b", 1, {14, 1.1, 3}, {-1, 0, 0}, 1.0, 2.2));
    l.start.room = 0;
    return l;
}

TEST(TracerPrismHoles, AnLsConcaveCornerHidesADoorOrLetsItBeSeenPastIt) {
    const layout::Layout l = l_with_door();
    const Scene scene = prepare_scene(l).value();
    EXPECT_EQ(scene.rooms[0].prism.faces[5].surface.holes, std::vector<int>{0});  // wall 3
    const dvec3 door(2.0, 1.1, 3.0);
    // From the south-west, past the corner: the door shows room 1.
    EXPECT_EQ(trace_ray(scene, {1.0, 1.5, 0.5}, door - dvec3(1.0, 1.5, 0.5), 0, 8).id, 2);
    // From the south-east the corner's other wall (2, z = 2, facing -z) hides it.
    const TraceHit hidden = trace_ray(scene, {3.5, 1.5, 0.5}, door - dvec3(3.5, 1.5, 0.5), 0, 8);
    EXPECT_EQ(hidden.id, 1);
    EXPECT_NEAR(hidden.point.z, 2.0, 1e-12);
    EXPECT_EQ(hidden.normal, dvec3(0, 0, -1));
    // Aimed exactly at the corner: one of its two walls.
    const dvec3 corner(2.0, 1.1, 2.0);
    const TraceHit at = trace_ray(scene, {1.0, 1.5, 0.5}, corner - dvec3(1.0, 1.5, 0.5), 0, 8);
    EXPECT_EQ(at.id, 1);
    test::expect_point(at.point, corner, 1e-12);
    // Frames from the south arm facing the corner's region: the door (room
    // 1) in sight past the corner from the west, hidden from the east.
    TraceDesc desc;
    desc.eye_width = 40;
    desc.eye_height = 30;
    desc.head = {{0.8, 1.5, 0.4}, holes_yaw_along(door - dvec3(0.8, 1.5, 0.4)), 0.0, 0.0};
    const image::Image west = trace_frame(scene, desc).value();
    EXPECT_GT(test::count_id(west, 2), 0);
    EXPECT_EQ(test::count_id(west, 1) + test::count_id(west, 2), 2 * 40 * 30);
    desc.head = {{3.6, 1.5, 0.4}, holes_yaw_along(door - dvec3(3.6, 1.5, 0.4)), 0.0, 0.0};
    const image::Image east = trace_frame(scene, desc).value();
    EXPECT_EQ(test::count_id(east, 1), 2 * 40 * 30);
}

// Under "lights", a lamp in a box room shines through a door in an L's wall
// 1 (x = 4): a floor point in the L's south arm sees the lamp's image
// through the door; one in the north arm sees it through the door's
// rectangle too, but its shadow ray crosses the L's notch and meets wall 3.
TEST(TracerPrismHoles, AnLsWallsStopShadowRays) {
    layout::Layout l;
    l.source = "<test>";
    l.lighting = layout::Lighting::Lights;
    l.rooms.push_back(prism_room("ell", l_floor(), 0.0, 3.0));
    l.rooms.push_back(test::make_room("lamp", {10, 0, -1}, {14, 3, 3}));
    for (layout::Room& r : l.rooms) r.ambient = dvec3(0.1);
    layout::Light light;
    light.position = {12, 2.9, 1};
    light.intensity = 20.0;
    l.rooms[1].lights.push_back(light);
    add_pair(l, make_portal("a", 0, {4, 1.5, 1}, {-1, 0, 0}, 1.9, 2.8),
             make_portal("b", 1, {10, 1.5, 1}, {1, 0, 0}, 1.9, 2.8));
    l.start.room = 0;
    const Scene scene = prepare_scene(l).value();
    const dvec3 floor_color = l.rooms[0].face_color[0];
    auto seen = [&](dvec3 eye, dvec3 p) {
        const TraceHit hit = trace_ray(scene, eye, p - eye, 0, RayLimits{8});
        EXPECT_EQ(hit.id, 1);
        test::expect_point(hit.point, p, 1e-12);
        return hit.color;
    };
    // The lamp's image in the L is at (6, 2.9, 1): the north point's line to
    // it crosses x = 2 at z ≈ 2.82 (wall 3) and x = 4 at z ≈ 1.91 (the door).
    test::expect_point(seen({0.5, 1.5, 3.0}, {0.5, 0.0, 3.5}), floor_color * 0.1, 1e-12);
    const dvec3 lit = seen({1.0, 1.5, 1.5}, {1.0, 0.0, 1.0});
    EXPECT_GT(lit.x, floor_color.x * 0.1 + 0.01);
}

// The tracer finds the same holes as the loader (Portal::hole_face) in a
// layout file's prism rooms: a door in an L's wall beside its concave
// corner, a trapdoor turned in its floor, a door in a turned room's slanted
// wall, and a door standing free in the L.
TEST(TracerPrismHoles, TheTracersHolesAreTheLoaders) {
    const char* text = R"({
      "format": "impossible-layout", "version": 1,
      "start": { "room": "ell", "position": [1, 1.6, 1] },
      "rooms": [
        { "id": "ell", "floor": [[0, 0], [4, 0], [4, 2], [2, 2], [2, 4], [0, 4]], "y": [0, 3] },
        { "id": "cellar", "floor": [[1, -1.2], [3.2, 1], [1, 3.2], [-1.2, 1]], "y": [-3, 0] },
        { "id": "turned", "floor": [[19.267949192431, -2.732050807569], [22.732050807569, -0.732050807569],
                                    [20.732050807569, 2.732050807569], [17.267949192431, 0.732050807569]], "y": [0, 3] },
        { "id": "box", "min": [60, 0, -2], "max": [64, 3, 2] }
      ],
      "portals": [
        { "id": "trap_down", "room": "ell", "center": [1, 0, 1], "normal": [0, 1, 0], "up": [0.34202, 0, -0.93969],
          "width": 1, "height": 1.2, "target": "trap_up" },
        { "id": "trap_up", "room": "cellar", "center": [1, 0, 1], "normal": [0, -1, 0], "up": [0.34202, 0, -0.93969],
          "width": 1, "height": 1.2, "target": "trap_down" },
        { "id": "ell_turned", "room": "ell", "center": [2, 1.1, 3], "normal": [-1, 0, 0], "width": 1, "height": 2.2,
          "target": "turned_ell" },
        { "id": "turned_ell", "room": "turned", "center": [21.732050807569, 1.1, 1.0],
          "normal": [-0.866025403784, 0, -0.5], "width": 1, "height": 2.2, "target": "ell_turned" },
        { "id": "ell_box", "room": "ell", "center": [1, 1.1, 3], "normal": [0, 0, -1], "width": 0.8, "height": 2,
          "target": "box_ell" },
        { "id": "box_ell", "room": "box", "center": [60, 1.1, 0], "normal": [1, 0, 0], "width": 0.8, "height": 2,
          "target": "ell_box" }
      ]
    })";
    const layout::LoadResult loaded = layout::load_layout_text(text, "<test>", ".");
    ASSERT_TRUE(loaded.errors.empty()) << loaded.errors.front().str();
    const layout::Layout& l = *loaded.layout;
    const Scene scene = prepare_scene(l).value();
    for (std::size_t p = 0; p < l.portals.size(); ++p) {
        int traced_face = -1;
        const SceneRoom& room = scene.rooms[std::size_t(l.portals[p].room)];
        for (std::size_t f = 0; f < room.prism.faces.size(); ++f)
            for (int h : room.prism.faces[f].surface.holes)
                if (h == static_cast<int>(p)) traced_face = static_cast<int>(f);
        for (int f = 0; f < layout::kFaceCount && room.prism.faces.empty(); ++f)
            for (int h : room.faces[f].holes)
                if (h == static_cast<int>(p)) traced_face = f;
        EXPECT_EQ(traced_face, l.portals[p].hole_face) << l.portals[p].id;
    }
    EXPECT_EQ(l.portals[0].hole_face, 0);   // the ell's floor
    EXPECT_EQ(l.portals[1].hole_face, 1);   // the cellar's ceiling
    EXPECT_EQ(l.portals[2].hole_face, 5);   // the ell's wall 3
    EXPECT_EQ(l.portals[3].hole_face, 3);   // the turned room's wall 1
    EXPECT_EQ(l.portals[4].hole_face, -1);  // free-standing
    EXPECT_EQ(l.portals[5].hole_face, int(layout::Face::NegX));
}

}  // namespace
}  // namespace impossible::trace
