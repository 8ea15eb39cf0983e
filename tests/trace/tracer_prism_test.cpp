// Prism rooms in the tracer (layout-format.md, "Rooms of any shape"): every
// face of an L-shaped and a turned room hit with its normal and colour, both
// windings; an eye 1 mm from a slanted wall; closed prism rooms show
// themselves at every pixel; grazing views and rays aimed exactly at the
// shared corners of a curved corridor's 24 walls never escape; textures run
// along walls; a light lights slanted walls by their own normals.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "layout/room_shape.hpp"
#include "math/polygon.hpp"
#include "trace/material_test_util.hpp"
#include "trace/prism_test_util.hpp"
#include "trace/trace_test_util.hpp"
#include "trace/tracer.hpp"

namespace impossible::trace {
namespace {

using test::curved_corridor;
using test::inward_normal;
using test::l_floor;
using test::prism_layout;
using test::shade_by_hand;
using test::turned_square;
using test::wall_point;

void expect_unit_near(const dvec3& got, const dvec3& want) {
    EXPECT_NEAR(got.x, want.x, 1e-15);
    EXPECT_NEAR(got.y, want.y, 1e-15);
    EXPECT_NEAR(got.z, want.z, 1e-15);
}

// Each wall, the floor and the ceiling seen head-on-ish from 0.5 m inside:
// the hit lies where the ray was aimed, with the face's normal into the room
// (worked out by hand) and its own colour, shaded (no checker).
void expect_every_face_hit(const std::vector<glm::dvec2>& floor, bool clockwise) {
    const layout::Layout l = prism_layout(floor);
    const Scene scene = prepare_scene(l).value();
    const int walls = static_cast<int>(floor.size());
    for (int i = 0; i < walls; ++i) {
        SCOPED_TRACE("wall " + std::to_string(i) + (clockwise ? ", clockwise" : ""));
        const dvec3 n = inward_normal(floor, i, clockwise);
        for (double along : {0.05, 0.3, 0.95}) {
            const dvec3 p = wall_point(floor, i, 1.2, along);
            const dvec3 eye = (0.5 * (wall_point(floor, i, 1.2, 0.5) + p)) + 0.5 * n + dvec3(0.0, 0.3, 0.0);
            const TraceHit hit = trace_ray(scene, eye, p - eye, 0, 8);
            ASSERT_EQ(hit.id, 1);
            test::expect_point(hit.point, p, 1e-12);
            expect_unit_near(hit.normal, n);
            const dvec3 want = shade_by_hand(l.rooms[0].face_color[static_cast<std::size_t>(2 + i)], n, false);
            test::expect_point(hit.color, want, 1e-12);
        }
    }
    // Floor and ceiling below and above a point 0.5 m inside wall 0.
    const dvec3 inside = wall_point(floor, 0, 1.5) + 0.5 * inward_normal(floor, 0, clockwise);
    for (int f = 0; f < 2; ++f) {
        const dvec3 n(0.0, f == 0 ? 1.0 : -1.0, 0.0);
        const dvec3 p(inside.x + 0.1, f == 0 ? 0.0 : 3.0, inside.z);
        const TraceHit hit = trace_ray(scene, inside, p - inside, 0, 8);
        ASSERT_EQ(hit.id, 1);
        test::expect_point(hit.point, p, 1e-12);
        EXPECT_EQ(hit.normal, n);
        test::expect_point(hit.color, shade_by_hand(l.rooms[0].face_color[std::size_t(f)], n, false), 1e-12);
    }
}

TEST(TracerPrism, EveryFaceOfAnLShapedRoomIsHitWithItsNormalAndColour) {
    std::vector<glm::dvec2> floor = l_floor();
    expect_every_face_hit(floor, false);
    std::reverse(floor.begin(), floor.end());
    expect_every_face_hit(floor, true);
}

TEST(TracerPrism, EveryFaceOfATurnedRoomIsHitWithItsNormalAndColour) {
    expect_every_face_hit(turned_square({1.0, -2.0}, 2.0, 30.0), false);
    expect_every_face_hit(turned_square({1.0, -2.0}, 2.0, 30.0, true), true);
    expect_every_face_hit(turned_square({0.0, 0.0}, 1.5, -71.3), false);
}

TEST(TracerPrism, EveryFaceOfACurvedCorridorIsHitWithItsNormalAndColour) {
    expect_every_face_hit(curved_corridor(), false);
}

// The number of pixels of both eyes showing room 1 from `head`.
long pixels_showing_the_room(const Scene& scene, math::HeadPose head, int width = 40, int height = 30) {
    TraceDesc desc;
    desc.head = head;
    desc.eye_width = width;
    desc.eye_height = height;
    const image::Image image = trace_frame(scene, desc).value();
    return test::count_id(image, 1);
}

// The yaw that looks along the horizontal direction d (yaw 0 looks along -z,
// positive yaw turns left).
double yaw_along(dvec3 d) { return std::atan2(-d.x, -d.z) * 180.0 / std::numbers::pi; }

TEST(TracerPrism, AClosedPrismRoomShowsItselfAtEveryPixel) {
    struct Case {
        std::vector<glm::dvec2> floor;
        dvec3 head;
    };
    const Case cases[] = {
        {l_floor(), {1.0, 1.6, 1.0}},          {l_floor(), {1.0, 1.6, 3.5}},
        {l_floor(), {3.5, 1.6, 0.5}},          {turned_square({0.0, 0.0}, 2.0, 30.0), {0.3, 1.6, -0.4}},
        {curved_corridor(), {0.3, 1.6, 3.74}}, {curved_corridor(), {3.74, 1.6, 0.3}},
        {curved_corridor(), {2.65, 1.6, 2.65}}};
    for (const Case& c : cases) {
        const Scene scene = prepare_scene(prism_layout(c.floor)).value();
        for (double yaw = 0.0; yaw < 360.0; yaw += 45.0)
            for (double pitch : {-30.0, 0.0, 30.0})
                EXPECT_EQ(pixels_showing_the_room(scene, {c.head, yaw, pitch, 0.0}), 2 * 40 * 30)
                    << c.head.x << ", " << c.head.z << " yaw " << yaw << " pitch " << pitch;
    }
}

TEST(TracerPrism, AnEyeAMillimetreFromASlantedWallSeesIt) {
    const std::vector<glm::dvec2> floor = turned_square({0.0, 0.0}, 2.0, 30.0);
    const layout::Layout l = prism_layout(floor);
    const Scene scene = prepare_scene(l).value();
    for (int i = 0; i < 4; ++i) {
        const dvec3 n = inward_normal(floor, i);
        const dvec3 on_wall = wall_point(floor, i, 1.5, 0.3);
        const dvec3 eye = on_wall + 0.001 * n;
        // Straight at the wall: 1 mm away, the wall's normal and colour.
        const TraceHit hit = trace_ray(scene, eye, -n, 0, 8);
        ASSERT_EQ(hit.id, 1);
        test::expect_point(hit.point, on_wall, 1e-12);
        expect_unit_near(hit.normal, n);
        // Facing the wall, along it and away from it, whole frames, the
        // nearer eye (32 mm from the head along its right) 1 mm from the
        // wall: every pixel.
        for (double turn : {0.0, 45.0, 90.0, 180.0, 270.0}) {
            const double away = 0.001 + 0.032 * std::abs(std::sin(turn * std::numbers::pi / 180.0));
            for (double pitch : {-40.0, 0.0, 40.0})
                EXPECT_EQ(pixels_showing_the_room(scene, {on_wall + away * n, yaw_along(-n) + turn, pitch, 0.0}),
                          2 * 40 * 30)
                    << "wall " << i << " turn " << turn << " pitch " << pitch;
        }
    }
}

// Rays aimed exactly at every corner of the corridor's walls (at mid height,
// and at the floor's and the ceiling's corners) from eyes along it, some a
// millimetre from a wall so that many rays graze the walls: each meets the
// room. Where the segment from the eye to the corner lies inside the floor
// polygon (the corner is in sight) the ray meets it there, on one of the
// two walls that share it (or the floor or the ceiling at their corners).
TEST(TracerPrism, RaysAtTheCurvedCorridorsWallCornersNeverEscape) {
    const std::vector<glm::dvec2> floor = curved_corridor();
    const layout::Layout l = prism_layout(floor);
    const Scene scene = prepare_scene(l).value();
    const int n = static_cast<int>(floor.size());
    ASSERT_EQ(n, 24);
    // Eyes 1 mm and 0.7 m from outer, inner and end walls.
    std::vector<dvec3> eyes;
    for (int k : {0, 5, 10, 11, 12, 17, 22, 23})
        for (double along : {0.1, 0.5, 0.9})
            for (double away : {0.001, 0.7})
                eyes.push_back(wall_point(floor, k, 1.37, along) + away * inward_normal(floor, k));
    int seen = 0;
    for (const dvec3& eye : eyes) {
        for (int k = 0; k < n; ++k) {
            const glm::dvec2 c = floor[static_cast<std::size_t>(k)];
            for (double y : {0.0, 1.5, 3.0}) {
                const dvec3 corner(c.x, y, c.y);
                const TraceHit hit = trace_ray(scene, eye, corner - eye, 0, 8);
                ASSERT_EQ(hit.id, 1) << "eye " << eye.x << ", " << eye.z << " corner " << k << " y " << y;
                if (!math::segment_inside(floor, {eye.x, eye.z}, c, 0.0)) continue;
                ++seen;
                test::expect_point(hit.point, corner, 1e-9);
                const dvec3 before = inward_normal(floor, (k + n - 1) % n), after = inward_normal(floor, k);
                const bool on_wall =
                    glm::length(hit.normal - before) < 1e-12 || glm::length(hit.normal - after) < 1e-12;
                EXPECT_TRUE(on_wall || (y != 1.5 && std::abs(hit.normal.y) == 1.0))
                    << "eye " << eye.x << ", " << eye.z << " corner " << k << " y " << y;
            }
        }
    }
    EXPECT_GT(seen, 500);
}

// Grazing views along the corridor: eyes on its centre line and a
// millimetre from its walls, looking along it both ways.
TEST(TracerPrism, GrazingViewsAlongACurvedCorridorShowOnlyItsWalls) {
    const Scene scene = prepare_scene(prism_layout(curved_corridor())).value();
    // Heads 35 mm from a wall (the eyes 3 mm and 67 mm), looking along it
    // both ways and 3° off it, and on the centre line.
    const std::vector<glm::dvec2> floor = curved_corridor();
    for (int k : {1, 5, 9, 13, 17, 21}) {
        const dvec3 n = inward_normal(floor, k);
        const dvec3 along(-n.z, 0.0, n.x);
        for (double away : {0.035, 0.75}) {
            const dvec3 head = wall_point(floor, k, 1.6) + away * n;
            for (double yaw : {yaw_along(along), yaw_along(-along), yaw_along(along) + 3.0})
                EXPECT_EQ(pixels_showing_the_room(scene, {head, yaw, 0.0, 0.0}, 64, 36), 2 * 64 * 36)
                    << "wall " << k << ", " << away << " m away, yaw " << yaw;
        }
    }
}

// Texture tiles run along a wall from its first corner, towards the right of
// a viewer inside facing it: on a turned room's walls (4 m long), one tile
// per 2 m, the texel centres of the image's top-left, top-right and
// bottom-left quadrants lie 0.5 m and 1.5 m along the wall from corner i
// and at y = 1.5 and 0.5. Clockwise, the viewer's right points from corner
// i + 1 back past corner i, so the left column lies 1.5 m along.
TEST(TracerPrism, WallTexturesRunAlongTheWall) {
    for (bool clockwise : {false, true}) {
        const std::vector<glm::dvec2> floor = turned_square({0.5, -0.5}, 2.0, 30.0, clockwise);
        layout::Layout l = prism_layout(floor);
        layout::Room& room = l.rooms[0];
        room.texture_size = 2.0;
        for (auto& t : room.face_texture) t = test::quadrants();
        const Scene scene = prepare_scene(l).value();
        const dvec3 eye(0.5, 1.6, -0.5);
        for (int i = 0; i < 4; ++i) {
            const dvec3 n = inward_normal(floor, i, clockwise);
            const double left = clockwise ? 0.375 : 0.125, right = clockwise ? 0.125 : 0.375;  // of 4 m
            const std::pair<dvec3, glm::dvec4> points[] = {{wall_point(floor, i, 1.5, left), test::quadrant(0, 0)},
                                                           {wall_point(floor, i, 1.5, right), test::quadrant(1, 0)},
                                                           {wall_point(floor, i, 0.5, left), test::quadrant(0, 1)}};
            for (const auto& [p, texel] : points) {
                const TraceHit hit = trace_ray(scene, eye, p - eye, 0, 8);
                ASSERT_EQ(hit.id, 1);
                const dvec3 want = shade_by_hand(room.face_color[std::size_t(2 + i)] * dvec3(texel), n, false);
                test::expect_point(hit.color, want, 1e-9);
                // The same place as layout::wall_uv gives, up to whole tiles.
                const glm::dvec2 uv = layout::wall_uv(room, i, p, room.texture_size);
                const glm::dvec2 frac = uv - glm::floor(uv);
                EXPECT_NEAR(frac.x, texel == test::quadrant(1, 0) ? 0.75 : 0.25, 1e-12);
                EXPECT_NEAR(frac.y, texel == test::quadrant(0, 1) ? 0.75 : 0.25, 1e-12);
            }
        }
    }
}

// Under "lights", a point light in a turned room lights its floor and its
// slanted walls by the spec's formula, base · (ambient + I · cos / d²), the
// cosine taken with each wall's own normal (worked out by hand).
TEST(TracerPrism, ALightInATurnedRoomLightsItsFacesByTheFormula) {
    const std::vector<glm::dvec2> floor = turned_square({0.0, 0.0}, 2.0, 30.0);
    layout::Layout l = prism_layout(floor);
    l.lighting = layout::Lighting::Lights;
    l.rooms[0].ambient = dvec3(0.1);
    layout::Light light;
    light.position = {0.2, 2.5, -0.1};
    light.intensity = 4.0;
    l.rooms[0].lights.push_back(light);
    const Scene scene = prepare_scene(l).value();
    const dvec3 eye(-0.3, 1.2, 0.4);
    auto expect_lit = [&](const dvec3& p, const dvec3& n, const dvec3& base) {
        const TraceHit hit = trace_ray(scene, eye, p - eye, 0, RayLimits{8});
        ASSERT_EQ(hit.id, 1);
        const dvec3 v = light.position - p;
        const double d2 = glm::dot(v, v);
        const double cosine = glm::dot(v, n) / std::sqrt(d2);
        test::expect_point(hit.color, glm::clamp(base * (0.1 + 4.0 * cosine / d2), 0.0, 1.0), 1e-12);
    };
    expect_lit({0.5, 0.0, -0.3}, {0, 1, 0}, l.rooms[0].face_color[0]);
    for (int i = 0; i < 4; ++i)
        expect_lit(wall_point(floor, i, 1.5, 0.4), inward_normal(floor, i), l.rooms[0].face_color[std::size_t(2 + i)]);
}

}  // namespace
}  // namespace impossible::trace
