// Lights in the tracer (layout-format.md, "Lights"): the inverse square,
// the cosine, the range window, the spot's band, light through a turned
// door, a mirror's and a window's images of a lamp, the light depth, a
// prop's shadow, a room overlapping another, and View::light_depth. Every
// expected colour is computed by hand in the comments from the spec's
// formulas: colour = base · (ambient + Σ I · factor · cos / d² · window · spot).
#include <cmath>

#include <gtest/gtest.h>

#include "trace/material_test_util.hpp"
#include "trace/trace_test_util.hpp"
#include "trace/tracer.hpp"

namespace impossible::trace::lights_test {
namespace {

using test::add_pair;
using test::make_mirror;
using test::make_portal;
using test::make_room;
using test::make_window;

// Lit colours are sums of a few terms: exact to rounding.
constexpr double kLitTol = 1e-12;
const dvec3 kLightsAmbient{0.1, 0.1, 0.1};

// make_room's floor colour (face 0).
const dvec3 kFloor{0.1, 0.5, 0.9};

layout::Light point_light(dvec3 position, double intensity, dvec3 color = dvec3(1.0)) {
    layout::Light light;
    light.position = position;
    light.intensity = intensity;
    light.color = color;
    return light;
}

// One room [-2, 0, -2]..[2, 3, 2] (or the given box) under "lights".
layout::Layout lit_room(dvec3 min = {-2, 0, -2}, dvec3 max = {2, 3, 2}) {
    layout::Layout l;
    l.source = "<test>";
    l.rooms.push_back(make_room("room", min, max));
    l.lighting = layout::Lighting::Lights;
    l.rooms[0].ambient = kLightsAmbient;
    return l;
}

// base · (ambient + sum), clamped, written out (no checker: dark = 1).
dvec3 lit_by_hand(dvec3 base, dvec3 sum = dvec3(0.0), dvec3 ambient = kLightsAmbient) {
    return glm::clamp(base * (ambient + sum), 0.0, 1.0);
}

void expect_color(const dvec3& got, const dvec3& want) {
    EXPECT_NEAR(got.x, want.x, kLitTol);
    EXPECT_NEAR(got.y, want.y, kLitTol);
    EXPECT_NEAR(got.z, want.z, kLitTol);
}

// The colour the tracer shows at floor point `p`, seen from `eye` in `room`.
dvec3 floor_seen(const Scene& scene, dvec3 eye, dvec3 p, int room = 0, int light_depth = -1) {
    const TraceHit hit = trace_ray(scene, eye, p - eye, room, RayLimits{8, 10'000, light_depth});
    EXPECT_EQ(hit.room, room);
    test::expect_point(hit.point, p, 1e-9);
    return hit.color;
}

TEST(TracerLights, APointLightHeadOnIsTheInverseSquare) {
    // Intensity 2 at (0, 2, 0) over the floor point (0, 0, 0): d = 2, cos = 1,
    // 2 / 4 = 0.5.
    layout::Layout l = lit_room();
    l.rooms[0].lights.push_back(point_light({0, 2, 0}, 2.0));
    const Scene scene = prepare_scene(l).value();
    expect_color(floor_seen(scene, {0, 1, 1}, {0, 0, 0}), lit_by_hand(kFloor, dvec3(0.5)));
}

TEST(TracerLights, TheLightsColourAndTheCosine) {
    // Intensity 5 at (1.5, 2, 0) over (0, 0, 0): v = (1.5, 2, 0), d = 2.5,
    // cos = 2 / 2.5 = 0.8, 1 / d² = 0.16: 5 · 0.8 · 0.16 = 0.64 times the colour.
    layout::Layout l = lit_room();
    const dvec3 color{1.0, 0.5, 0.25};
    l.rooms[0].lights.push_back(point_light({1.5, 2, 0}, 5.0, color));
    const Scene scene = prepare_scene(l).value();
    expect_color(floor_seen(scene, {0, 1, 1}, {0, 0, 0}), lit_by_hand(kFloor, 0.64 * color));
}

TEST(TracerLights, TheRangeWindowFadesTheLightToNothing) {
    // Intensity 4 at d = 2 with range 4: (d / range)⁴ = 1/16, window 15/16,
    // 4 / 4 · 15/16 = 0.9375. With range 1.5 < d: nothing.
    layout::Layout l = lit_room();
    l.rooms[0].lights.push_back(point_light({0, 2, 0}, 4.0));
    l.rooms[0].lights[0].range = 4.0;
    expect_color(floor_seen(prepare_scene(l).value(), {0, 1, 1}, {0, 0, 0}), lit_by_hand(kFloor, dvec3(0.9375)));
    l.rooms[0].lights[0].range = 1.5;
    expect_color(floor_seen(prepare_scene(l).value(), {0, 1, 1}, {0, 0, 0}), lit_by_hand(kFloor, dvec3(0.0)));
}

TEST(TracerLights, ASpotIsFullInsideItsInnerConeAndDarkOutsideItsOuter) {
    // A spot at (0, 2, 0) pointing down, inner 20°, outer 40°, intensity 4,
    // over the floor of a wider room at angle θ from its axis: x = 2 tan θ,
    // d = 2 / cos θ, cos at the floor = cos θ,
    // spot = ((cos θ - cos 40°) / (cos 20° - cos 40°))² clamped.
    layout::Layout l = lit_room({-4, 0, -4}, {4, 3, 4});
    layout::Light spot = point_light({0, 2, 0}, 4.0);
    spot.spot = layout::Spot{{0, -1, 0}, 20.0, 40.0};
    l.rooms[0].lights.push_back(spot);
    const Scene scene = prepare_scene(l).value();
    const double pi = 3.14159265358979323846;
    const double cos20 = std::cos(20.0 * pi / 180.0), cos40 = std::cos(40.0 * pi / 180.0);
    auto at_angle = [&](double deg) {
        const double c = std::cos(deg * pi / 180.0);
        const double band = std::clamp((c - cos40) / (cos20 - cos40), 0.0, 1.0);
        return 4.0 * c * (c * c / 4.0) * band * band;
    };
    // θ = 0: the axis, spot 1, 4 / 4 = 1.
    expect_color(floor_seen(scene, {0.5, 1, 1}, {0, 0, 0}), lit_by_hand(kFloor, dvec3(1.0)));
    EXPECT_EQ(at_angle(0.0), 1.0);
    // θ = 10° (inside the inner cone): spot 1.
    const double x10 = 2.0 * std::tan(10.0 * pi / 180.0);
    expect_color(floor_seen(scene, {0, 1, 1}, {x10, 0, 0}),
                 lit_by_hand(kFloor, dvec3(4.0 * std::pow(std::cos(10.0 * pi / 180.0), 3) / 4.0)));
    // θ = 30° (in the band): 0 < spot < 1.
    const double band30 = (std::cos(30.0 * pi / 180.0) - cos40) / (cos20 - cos40);
    EXPECT_GT(band30, 0.0);
    EXPECT_LT(band30, 1.0);
    expect_color(floor_seen(scene, {0, 1, 1}, {2.0 * std::tan(30.0 * pi / 180.0), 0, 0}),
                 lit_by_hand(kFloor, dvec3(at_angle(30.0))));
    // θ = 45° (outside the outer cone): nothing.
    expect_color(floor_seen(scene, {0, 1, 1}, {2.0, 0, 0}), lit_by_hand(kFloor, dvec3(0.0)));
}

// Hall [-2, 0, -2]..[2, 3, 2] with a door in its -z wall (centre (0, 1, -2),
// 1 × 2, x in [-0.5, 0.5], y in [0, 2]) to a room [10, 0, -2]..[14, 3, 2]
// through a door in that room's +x wall (centre (14, 1, 0), facing -x):
// turned by 90°. M_AB (p) = (p.z + 16, p.y, -p.x), M_AB⁻¹ (q) = (-q.z, q.y, q.x - 16).
layout::Layout turned_rooms() {
    layout::Layout l = lit_room();
    l.rooms.push_back(make_room("side", {10, 0, -2}, {14, 3, 2}));
    l.rooms[1].ambient = dvec3(0.3);
    add_pair(l, make_portal("hall_door", 0, {0, 1, -2}, {0, 0, 1}),
             make_portal("side_door", 1, {14, 1, 0}, {-1, 0, 0}));
    // Intensity 13 at (12, 2, 0) in the side room: its image in the hall is (0, 2, -4).
    l.rooms[1].lights.push_back(point_light({12, 2, 0}, 13.0));
    return l;
}

TEST(TracerLights, LightComesThroughATurnedDoor) {
    const Scene scene = prepare_scene(turned_rooms()).value();
    // Floor point (0, 0, -1) → image (0, 2, -4): v = (0, 2, -3), d² = 13,
    // crossing z = -2 at t = 1/3, (0, 2/3): in the door. cos = 2 / √13:
    // 13 · (2 / √13) / 13 = 2 / √13.
    expect_color(floor_seen(scene, {0, 1.5, 1}, {0, 0, -1}), lit_by_hand(kFloor, dvec3(2.0 / std::sqrt(13.0))));
    // Floor point (1.5, 0, -1): the segment crosses z = -2 at x = 1: the wall.
    expect_color(floor_seen(scene, {0, 1.5, 1}, {1.5, 0, -1}), lit_by_hand(kFloor));
    // The side room's own floor under its lamp, with its own ambient: 13 / 4.
    expect_color(floor_seen(scene, {13, 1.5, 1}, {12, 0, 0}, 1), lit_by_hand(kFloor, dvec3(13.0 / 4.0), dvec3(0.3)));
    // Light depth 0: the hall sees no light of the side room.
    expect_color(floor_seen(scene, {0, 1.5, 1}, {0, 0, -1}, 0, 0), lit_by_hand(kFloor));
}

TEST(TracerLights, AMirrorDoublesALampWithItsTint) {
    // A 2 × 2 mirror in the -z wall (x in [-1, 1], y in [0.5, 2.5]), tint
    // (0.5, 0.8, 1); a lamp of intensity 1 at (0, 2, 0); the floor point
    // (0, 0, 1). Direct: v = (0, 2, -1), d² = 5, cos = 2 / √5: 2 / (5 √5).
    // In the mirror: image (0, 2, -4), v = (0, 2, -5), d² = 29, crossing
    // z = -2 at t = 3/5, y = 1.2 (in the mirror), cos = 2 / √29: 2 / (29 √29) · tint.
    layout::Layout l = lit_room();
    const dvec3 tint{0.5, 0.8, 1.0};
    l.portals.push_back(make_mirror("mirror", 0, {0, 1.5, -2}, {0, 0, 1}, 2.0, 2.0, tint));
    l.rooms[0].lights.push_back(point_light({0, 2, 0}, 1.0));
    const Scene scene = prepare_scene(l).value();
    const double direct = 2.0 / (5.0 * std::sqrt(5.0));
    const double mirrored = 2.0 / (29.0 * std::sqrt(29.0));
    expect_color(floor_seen(scene, {0, 1.5, 1.5}, {0, 0, 1}), lit_by_hand(kFloor, direct + mirrored * tint));
    expect_color(floor_seen(scene, {0, 1.5, 1.5}, {0, 0, 1}, 0, 0), lit_by_hand(kFloor, dvec3(direct)));
    // The floor point (0, 0, -1.5): the image's segment crosses z = -2 at
    // t = 1/5, y = 0.4, below the mirror: the direct light only,
    // v = (0, 2, 1.5), d = 2.5, cos = 0.8: 0.8 / 6.25 = 0.128.
    expect_color(floor_seen(scene, {0, 1.5, 1.5}, {0, 0, -1.5}), lit_by_hand(kFloor, dvec3(0.128)));
}

TEST(TracerLights, AWindowLetsLightThroughAndReflectsIt) {
    // A 2 × 2 window (x in [-1, 1], y in [0.5, 2.5]) in the hall's -z wall,
    // r = 0.25, tint 0.5, paired with one facing the other way in the same
    // place in the +z wall of a room [-2, 0, -6]..[2, 3, -2] (M_AB = identity).
    layout::Layout l = lit_room();
    l.rooms.push_back(make_room("beyond", {-2, 0, -6}, {2, 3, -2}));
    add_pair(l, make_window("w_hall", 0, {0, 1.5, -2}, {0, 0, 1}, 2.0, 2.0, dvec3(0.5), 0.25),
             make_window("w_beyond", 1, {0, 1.5, -2}, {0, 0, -1}, 2.0, 2.0, dvec3(0.5), 0.25));
    l.rooms[0].lights.push_back(point_light({0, 2, 0}, 1.0));
    l.rooms[1].lights.push_back(point_light({0.5, 2, -3}, 4.0));
    const Scene scene = prepare_scene(l).value();
    // At (0, 0, 1): the hall's lamp direct, 2 / (5 √5); reflected (image
    // (0, 2, -4), as in the mirror test) times r = 0.25, 0.25 · 2 / (29 √29);
    // the other room's lamp through: v = (0.5, 2, -4), d = 4.5, crossing
    // z = -2 at t = 3/4, (0.375, 1.5), cos = 2 / 4.5, factor (1 - r) · tint = 0.375:
    // 4 · 0.375 · (2 / 4.5) / 20.25.
    const double direct = 2.0 / (5.0 * std::sqrt(5.0));
    const double reflected = 0.25 * 2.0 / (29.0 * std::sqrt(29.0));
    const double through = 4.0 * 0.375 * (2.0 / 4.5) / 20.25;
    expect_color(floor_seen(scene, {0, 1.5, 1.5}, {0, 0, 1}), lit_by_hand(kFloor, dvec3(direct + reflected + through)));
    expect_color(floor_seen(scene, {0, 1.5, 1.5}, {0, 0, 1}, 0, 0), lit_by_hand(kFloor, dvec3(direct)));
}

// Three rooms in a row along -z, each door 2 × 2 (x in [-1, 1], y in
// [0.5, 2.5]) in the shared walls z = -2 and z = -6, pairs coincident
// (M_AB = identity): hall [-2, 2], middle [-6, -2], far [-10, -6] in z.
layout::Layout three_rooms() {
    layout::Layout l = lit_room();
    l.rooms.push_back(make_room("middle", {-2, 0, -6}, {2, 3, -2}));
    l.rooms.push_back(make_room("far", {-2, 0, -10}, {2, 3, -6}));
    add_pair(l, make_portal("h", 0, {0, 1.5, -2}, {0, 0, 1}, 2.0, 2.0),
             make_portal("m1", 1, {0, 1.5, -2}, {0, 0, -1}, 2.0, 2.0));
    add_pair(l, make_portal("m2", 1, {0, 1.5, -6}, {0, 0, 1}, 2.0, 2.0),
             make_portal("f", 2, {0, 1.5, -6}, {0, 0, -1}, 2.0, 2.0));
    l.rooms[1].lights.push_back(point_light({1, 1.5, -4}, 18.5));
    l.rooms[2].lights.push_back(point_light({0, 1.5, -8}, 25.0));
    return l;
}

// The hall's +z wall (colour (0.6, 0.5, 0.9), normal -z) at (0, 1.5, 2),
// seen from (0, 1.5, 0).
dvec3 back_wall_seen(const Scene& scene, int light_depth) {
    const TraceHit hit = trace_ray(scene, {0, 1.5, 0}, {0, 0, 1}, 0, RayLimits{8, 10'000, light_depth});
    test::expect_point(hit.point, {0, 1.5, 2});
    return hit.color;
}

TEST(TracerLights, PathsAppearAsTheLightDepthGrows) {
    // From (0, 1.5, 2): the middle lamp, v = (1, 0, -6), d² = 37, crossing
    // z = -2 at t = 2/3, x = 2/3 (in the door), cos = 6 / √37: 18.5 · (6 / √37) / 37;
    // the far lamp, v = (0, 0, -10), through both doors' centres, cos = 1:
    // 25 / 100 = 0.25.
    const layout::Layout l = three_rooms();
    const Scene scene = prepare_scene(l).value();
    const dvec3 wall{0.6, 0.5, 0.9};
    const double middle = 3.0 / std::sqrt(37.0), far = 0.25;
    expect_color(back_wall_seen(scene, 0), lit_by_hand(wall, dvec3(0.0)));
    expect_color(back_wall_seen(scene, 1), lit_by_hand(wall, dvec3(middle)));
    expect_color(back_wall_seen(scene, 2), lit_by_hand(wall, dvec3(middle + far)));
    expect_color(back_wall_seen(scene, 16), lit_by_hand(wall, dvec3(middle + far)));
    // -1: the layout's light_depth (2 by default).
    EXPECT_EQ(back_wall_seen(scene, -1), back_wall_seen(scene, 2));
}

TEST(TracerLights, APropCastsAShadow) {
    // A slab [-0.25, 0.25] × [0.9, 1] × [-0.25, 0.25] under a lamp of
    // intensity 1 at (0, 2, 0): the floor's centre is in its shadow; at
    // (1.5, 0, 0) the segment passes y = 0.9..1 at x ≈ 0.8: lit,
    // v = (-1.5, 2, 0), d = 2.5, cos = 0.8: 0.128.
    layout::Layout l = lit_room();
    l.rooms[0].props.push_back(layout::BoxProp{{-0.25, 0.9, -0.25}, {0.25, 1.0, 0.25}, test::kRed, {}, {}});
    l.rooms[0].lights.push_back(point_light({0, 2, 0}, 1.0));
    const Scene scene = prepare_scene(l).value();
    expect_color(floor_seen(scene, {1, 1.5, 1}, {0, 0, 0}), lit_by_hand(kFloor));
    expect_color(floor_seen(scene, {1, 1.5, 1}, {1.5, 0, 0}), lit_by_hand(kFloor, dvec3(0.128)));
    // The slab's top, facing the lamp 1 m above: 1 / 1 = 1 (red).
    const TraceHit top = trace_ray(scene, {0.5, 2.5, 0.5}, {-0.5, -1.5, -0.5}, 0, 8);
    test::expect_point(top.point, {0, 1, 0}, 1e-9);
    expect_color(top.color, lit_by_hand(test::kRed, dvec3(1.0)));
}

// Hall and annex fill the same box, joined by a free-standing door at
// z = 0 (x in [-0.5, 0.5], y in [0, 2.2]) facing +z in the hall; a lamp of
// intensity 1 in the annex at (0, 2, -1).
layout::Layout overlapping_rooms() {
    layout::Layout l = lit_room();
    l.rooms.push_back(make_room("annex", {-2, 0, -2}, {2, 3, 2}));
    add_pair(l, make_portal("hall_door", 0, {0, 1.1, 0}, {0, 0, 1}, 1.0, 2.2),
             make_portal("annex_door", 1, {0, 1.1, 0}, {0, 0, -1}, 1.0, 2.2));
    l.rooms[1].lights.push_back(point_light({0, 2, -1}, 1.0));
    return l;
}

TEST(TracerLights, ALightOfAnOverlappingRoomComesOnlyThroughTheDoor) {
    const Scene scene = prepare_scene(overlapping_rooms()).value();
    // (0, 0, 1): v = (0, 2, -2), crossing z = 0 at (0, 1): through the door;
    // d² = 8, cos = 1 / √2: 1 / (8 √2). Light depth 0: nothing of the annex.
    expect_color(floor_seen(scene, {0, 1.5, 2}, {0, 0, 1}), lit_by_hand(kFloor, dvec3(1.0 / (8.0 * std::sqrt(2.0)))));
    expect_color(floor_seen(scene, {0, 1.5, 2}, {0, 0, 1}, 0, 0), lit_by_hand(kFloor));
    // (1.5, 0, 1): the segment crosses z = 0 at x = 0.75, beside the door:
    // the lamp stands in the same place in the annex's coordinates, but no
    // path leads there.
    expect_color(floor_seen(scene, {0, 1.5, 2}, {1.5, 0, 1}), lit_by_hand(kFloor));
    // Behind the door (z < 0 in the hall, seen beside it) the lamp is no
    // light of the hall, and the door's back lets nothing through.
    expect_color(floor_seen(scene, {1.5, 1.5, 1}, {1.5, 0, -1.5}), lit_by_hand(kFloor));
}

TEST(TracerLights, ViewLightDepthReplacesTheLayouts) {
    layout::Layout l = three_rooms();
    l.light_depth = 2;
    TraceDesc desc;
    desc.room = 0;
    desc.head.position = {0, 1.5, 0};
    desc.head.yaw_deg = 180.0;  // looking along +z, at the lit wall
    desc.eye_width = 32;
    desc.eye_height = 18;
    desc.threads = 2;
    const image::Image layouts = trace_frame(l, desc).value();
    desc.light_depth = 0;
    const image::Image replaced = trace_frame(l, desc).value();
    layout::Layout shallow = l;
    shallow.light_depth = 0;
    desc.light_depth.reset();
    const image::Image shallow_frame = trace_frame(shallow, desc).value();
    EXPECT_EQ(replaced.rgb, shallow_frame.rgb);
    EXPECT_NE(replaced.rgb, layouts.rgb);
    EXPECT_EQ(replaced.ids, layouts.ids);  // the id map does not depend on light
    desc.light_depth = 17;
    EXPECT_FALSE(trace_frame(l, desc));
    desc.light_depth = -1;
    EXPECT_FALSE(trace_frame(l, desc));
}

TEST(TracerLights, ALitFrameDoesNotDependOnTheThreads) {
    const layout::Layout l = turned_rooms();
    TraceDesc desc;
    desc.room = 0;
    desc.head.position = {0, 1.5, 1.5};
    desc.eye_width = 40;
    desc.eye_height = 24;
    desc.threads = 1;
    const image::Image one = trace_frame(l, desc).value();
    desc.threads = 3;
    const image::Image three = trace_frame(l, desc).value();
    EXPECT_EQ(one.rgb, three.rgb);
}

TEST(TracerLights, AMovingPropCastsItsShadowWhereTheFramePutsIt) {
    // The slab of APropCastsAShadow, sliding by (0.8, 0, 0) over 1 s: at
    // t = 0 it shades the floor's centre; at t = 1 (x in [0.55, 1.05]) the
    // centre is lit, 1 / 4, and (1.5, 0, 0), whose segment passes y = 0.9..1
    // at x = 0.75..0.825, is in its shadow.
    layout::Layout l = lit_room();
    layout::BoxProp slab{{-0.25, 0.9, -0.25}, {0.25, 1.0, 0.25}, test::kRed, "slab", {}};
    slab.motion.keys = {{0.0, {0, 0, 0}}, {1.0, {0.8, 0, 0}}};
    l.rooms[0].props.push_back(slab);
    l.rooms[0].lights.push_back(point_light({0, 2, 0}, 1.0));
    const Scene scene = prepare_scene(l).value();
    ASSERT_EQ(scene.props.size(), 1u);  // a dynamic object, placed per frame
    math::View later;
    later.time = 1.0;
    const FrameObjects moved = place_frame_objects(scene, later);
    auto seen = [&](const FrameObjects& objects, dvec3 p) {
        const dvec3 eye{1, 1.5, 1};
        return trace_ray(scene, eye, p - eye, 0, RayLimits{}, objects).color;
    };
    expect_color(seen(scene.rest, {0, 0, 0}), lit_by_hand(kFloor));
    expect_color(seen(scene.rest, {1.5, 0, 0}), lit_by_hand(kFloor, dvec3(0.128)));
    expect_color(seen(moved, {0, 0, 0}), lit_by_hand(kFloor, dvec3(0.25)));
    expect_color(seen(moved, {1.5, 0, 0}), lit_by_hand(kFloor));
}

TEST(TracerLights, ADoorBoxIsOnlyItsFrontForShadowRays) {
    // overlapping_rooms' door box reaches from z = 0 back to z = -0.25. A
    // hall lamp of intensity 1 at (0, 2, -1) lights the hall floor at
    // (0, 0, -0.1), in the box's column: the segment leaves through the
    // box's back face (z = -0.25 at y = 1/3), which a view ray from there
    // would meet, but a shadow ray does not. v = (0, 2, -0.9), d² = 4.81,
    // cos = 2 / √4.81.
    layout::Layout l = overlapping_rooms();
    l.rooms[1].lights.clear();
    l.rooms[0].lights.push_back(point_light({0, 2, -1}, 1.0));
    const Scene scene = prepare_scene(l).value();
    const double d2 = 4.81;
    expect_color(floor_seen(scene, {1.5, 1.5, -1}, {0, 0, -0.1}), lit_by_hand(kFloor, dvec3(2.0 / std::sqrt(d2) / d2)));
}

TEST(TracerLights, ALightPathAlongADoorsEdgeIsDecidedOnce) {
    // (1, 0, 1) to the annex lamp's image (0, 2, -1) crosses z = 0 at
    // x = 0.5, the door's edge: whatever the rounding there, the answer is
    // one of the two, finite, and the same every time.
    const Scene scene = prepare_scene(overlapping_rooms()).value();
    const dvec3 first = floor_seen(scene, {1, 1.5, 2}, {1, 0, 1});
    const double d2 = 1 + 4 + 4, lit = 2.0 / 3.0 / d2;  // v = (-1, 2, -2), d = 3, cos = 2 / 3
    const bool is_lit = std::abs(first.x - lit_by_hand(kFloor, dvec3(lit)).x) < kLitTol;
    const bool is_dark = std::abs(first.x - lit_by_hand(kFloor).x) < kLitTol;
    EXPECT_TRUE(is_lit || is_dark);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(floor_seen(scene, {1, 1.5, 2}, {1, 0, 1}), first);
}

// lab (0) and past (1) fill [-3, 3] × [0, 3] × [-3, 3]; a volume against
// lab's -z wall (x in [-1, 1], y in [0, 3], z in [-3, -2]) shows past,
// tinted. Past has its own ambient (0.2) and a lamp of intensity 1 at
// (0, 2, -2); lab a lamp at (0, 2, 0) and, inside the volume, a box
// [-0.5, 1.6, -2.8]..[0.5, 1.9, -2.2] that views there do not see.
layout::Layout lit_volume() {
    layout::Layout l = lit_room({-3, 0, -3}, {3, 3, 3});
    l.rooms.push_back(make_room("past", {-3, 0, -3}, {3, 3, 3}, {0, 0.2, 0.1}));
    l.rooms[1].ambient = dvec3(0.2);
    layout::Volume v;
    v.id = "scanner";
    v.room = 0;
    v.rect.center = {0, 1.5, -2.5};
    v.rect.normal = {0, 0, 1};
    v.rect.up = {0, 1, 0};
    v.rect.width = 2;
    v.rect.height = 3;
    v.rect.depth = 1;
    v.target_room = 1;
    v.tint = {0.5, 1.0, 0.8};
    l.volumes.push_back(v);
    l.rooms[0].lights.push_back(point_light({0, 2, 0}, 1.0));
    l.rooms[0].props.push_back(layout::BoxProp{{-0.5, 1.6, -2.8}, {0.5, 1.9, -2.2}, test::kRed, {}, {}});
    l.rooms[1].lights.push_back(point_light({0, 2, -2}, 1.0));
    return l;
}

TEST(TracerLights, AVolumesTargetIsLitByItsOwnLights) {
    const layout::Layout l = lit_volume();
    const Scene scene = prepare_scene(l).value();
    // Past's -z wall (colour (0.5, 0.2, 0.1)) at (0, 1.5, -3), seen inside
    // the volume: past's ambient and past's lamp only, v = (0, 0.5, 1),
    // d² = 1.25, cos = 1 / √1.25, through lab's hidden box (no surface of
    // past's), times the tint. Lab's lamp, in the same coordinates, is no
    // light of past.
    const TraceHit hit = trace_ray(scene, {0, 1.5, 1}, {0, 0, -1}, 0, RayLimits{});
    EXPECT_EQ(hit.room, 1);
    test::expect_point(hit.point, {0, 1.5, -3});
    const dvec3 past_wall{0.5, 0.2, 0.1};
    const dvec3 sum(1.0 / std::sqrt(1.25) / 1.25);
    expect_color(hit.color, lit_by_hand(past_wall, sum, dvec3(0.2)) * l.volumes[0].tint);
    // Lab's floor at (0, 0, 1): lab's lamp, 2 / (5 √5); past's is not lab's.
    expect_color(floor_seen(scene, {0, 1.5, 2}, {0, 0, 1}), lit_by_hand(kFloor, dvec3(2.0 / (5.0 * std::sqrt(5.0)))));
    // Lab's floor just in front of the volume, (0, 0, -1.5): lab's lamp,
    // v = (0, 2, 1.5), d = 2.5, cos = 0.8: 0.128.
    expect_color(floor_seen(scene, {0, 1.5, 2}, {0, 0, -1.5}), lit_by_hand(kFloor, dvec3(0.128)));
}

TEST(TracerLights, TwoFacingMirrorsStopAtTheFactorRule) {
    // Mirrors fill the -z wall (A, z = -2) and the +z wall (B, z = 2), tint
    // 0.5; a lamp of intensity 1 at (0, 2, 0.5); the floor point (0, 0, 0).
    // A path alternates A and B (a shadow ray cannot meet the mirror it left),
    // starting with either; its image is L reflected in P1, P2, … Pk taken
    // from the last (A: z → -4 - z, B: z → 4 - z), its factor 0.5^k, kept
    // while 0.5^k ≥ 1/256: k ≤ 8 even at light depth 16. With v = (0, 2, z),
    // cos = 2 / d: each adds 0.5^k · 2 / d³.
    layout::Layout l = lit_room();
    l.portals.push_back(make_mirror("a", 0, {0, 1.5, -2}, {0, 0, 1}, 4.0, 3.0, dvec3(0.5)));
    l.portals.push_back(make_mirror("b", 0, {0, 1.5, 2}, {0, 0, -1}, 4.0, 3.0, dvec3(0.5)));
    l.rooms[0].lights.push_back(point_light({0, 2, 0.5}, 1.0));
    const Scene scene = prepare_scene(l).value();
    auto by_hand = [](int depth) {
        auto term = [](double z, int k) { return std::pow(0.5, k) * 2.0 / std::pow(4.0 + z * z, 1.5); };
        double sum = term(0.5, 0);
        for (int first = 0; first < 2; ++first) {
            for (int k = 1; k <= std::min(depth, 8); ++k) {
                double z = 0.5;
                for (int i = k; i >= 1; --i) {
                    const bool a = (first + i - 1) % 2 == 0;  // P1 is `first`, then they alternate
                    z = a ? -4.0 - z : 4.0 - z;
                }
                sum += term(z, k);
            }
        }
        return sum;
    };
    for (int depth : {0, 1, 3, 8, 16}) {
        SCOPED_TRACE(depth);
        expect_color(floor_seen(scene, {1, 1.5, 0}, {0, 0, 0}, 0, depth), lit_by_hand(kFloor, dvec3(by_hand(depth))));
    }
    EXPECT_GT(by_hand(8), by_hand(3));
    EXPECT_EQ(by_hand(16), by_hand(8));
}

TEST(TracerLights, LightPassesAnAlphaCutOutAndNotTheRestOfTheModel) {
    // material_test_util's quad (x in [-1, 1], y in [0.5, 2.5] at z = -1,
    // facing +z), its top-right quadrant (x ≥ 0, y ≥ 1.5) alpha 0 under
    // MASK; a lamp of intensity 1 behind it at (0.5, 2, -1.5).
    layout::Layout l = lit_room();
    layout::GltfProp model;
    assets::Material material;
    material.texture = 0;
    material.alpha_mode = assets::AlphaMode::Mask;
    model.materials.push_back(material);
    model.textures.push_back(test::texture(test::quadrants(0), assets::sampler_code::kNearest));
    test::add_quad(model, 0);
    l.rooms[0].props.push_back(model);
    l.rooms[0].lights.push_back(point_light({0.5, 2, -1.5}, 1.0));
    const Scene scene = prepare_scene(l).value();
    // (0.5, 0, 1): v = (0, 2, -2.5) crosses z = -1 at t = 0.8, y = 1.6: the
    // cut-out. d² = 10.25, cos = 2 / √10.25.
    expect_color(floor_seen(scene, {0.5, 1.5, 2}, {0.5, 0, 1}),
                 lit_by_hand(kFloor, dvec3(2.0 / std::sqrt(10.25) / 10.25)));
    // (0.5, 0, 0): crosses at t = 2/3, y = 4/3, the opaque bottom-right quadrant.
    expect_color(floor_seen(scene, {0.5, 1.5, 2}, {0.5, 0, 0}), lit_by_hand(kFloor));
}

TEST(TracerLights, ALightTouchingTheSurfaceSaturatesWithoutNaN) {
    // A lamp 1e-155 m above the floor point (0, 0, 0) (built in code; the
    // loader would refuse it): 1 / d² overflows. Its red and blue saturate
    // (base · (0.1 + huge), clamped to 1); its green is 0, so green keeps the
    // ambient, 0.5 · 0.1, and no channel is NaN.
    layout::Layout l = lit_room();
    l.rooms[0].lights.push_back(point_light({0, 1e-155, 0}, 1.0, {1, 0, 1}));
    const Scene scene = prepare_scene(l).value();
    const TraceHit hit = trace_ray(scene, {0, 1, 1}, {0, -1, -1}, 0, RayLimits{});
    EXPECT_EQ(hit.point, dvec3(0.0));
    expect_color(hit.color, dvec3(1.0, 0.05, 1.0));
}

TEST(TracerLights, ARoomSplitByAWallSizedDoorIsLitAsTheWholeRoom) {
    // [-2, 2] × [0, 3] × [-6, 2] as one room, and cut at z = -2 into two
    // joined by coincident doors filling the whole wall (M_AB = identity):
    // every segment from one part to a lamp in the other crosses the door,
    // so each point's light is the same sum, once as k = 0 and once through
    // the door. The frames' colours agree; only the ids tell the parts apart.
    const dvec3 ambient(0.1);
    layout::Layout whole = lit_room({-2, 0, -6}, {2, 3, 2});
    whole.rooms[0].lights = {point_light({0.5, 2, 0.5}, 2.0), point_light({-0.7, 2.5, -4}, 3.0, {1, 0.6, 0.3})};
    layout::Layout split = lit_room();
    split.rooms.push_back(make_room("back", {-2, 0, -6}, {2, 3, -2}));
    split.rooms[1].ambient = ambient;
    add_pair(split, make_portal("front_door", 0, {0, 1.5, -2}, {0, 0, 1}, 4.0, 3.0),
             make_portal("back_door", 1, {0, 1.5, -2}, {0, 0, -1}, 4.0, 3.0));
    split.rooms[0].lights = {whole.rooms[0].lights[0]};
    split.rooms[1].lights = {whole.rooms[0].lights[1]};
    TraceDesc desc;
    desc.room = 0;
    desc.head.position = {0.3, 1.6, 1.5};
    desc.head.yaw_deg = 10.0;
    desc.head.pitch_deg = -20.0;
    desc.fov_y_deg = 100.0;
    desc.eye_width = 64;
    desc.eye_height = 36;
    desc.threads = 2;
    const image::Image one = trace_frame(whole, desc).value();
    const image::Image two = trace_frame(split, desc).value();
    ASSERT_EQ(one.rgb.size(), two.rgb.size());
    EXPECT_GT(test::count_id(two, 2), 500);  // much of the frame is the back part
    int worst = 0;
    for (std::size_t i = 0; i < one.rgb.size(); ++i) worst = std::max(worst, std::abs(one.rgb[i] - two.rgb[i]));
    EXPECT_EQ(worst, 0);
}

}  // namespace
}  // namespace impossible::trace::lights_test
