// Mirrors (layout-format.md, "Mirrors and windows" and "What a pixel shows",
// step 4): the room reflected, the tint, the recursion limit, two facing
// mirrors, an eye at contact distance, a mirror seen from behind, and
// mirrors and doors seen through each other. Expected hit points are
// computed by hand in the comments; where a whole view is checked, the
// expectation is the reflected ray traced directly in the room without the
// mirror.
#include <gtest/gtest.h>

#include "trace/trace_test_util.hpp"
#include "trace/tracer.hpp"

namespace impossible::trace {
namespace {

using test::expect_point;
using test::face_color;
using test::kFill;
using test::kRed;
using test::kTol;
using test::make_mirror;
using test::make_portal;
using test::make_room;
using test::shade_by_hand;

// The room without the mirror, with a red box on the floor to be seen in it.
layout::Layout plain_room() {
    layout::Layout l;
    l.rooms.push_back(make_room("room", {-2, 0, -2}, {2, 3, 2}));
    l.rooms[0].props.push_back(layout::BoxProp{{0.5, 0, 0.5}, {1.0, 0.8, 1.0}, kRed, {}, {}});
    return l;
}

// The same room with a 1 × 2 m mirror in its -z wall: x in [-0.5, 0.5],
// y in [0.5, 2.5] at z = -2, facing +Z. M_P maps (x, y, z) to (x, y, -4 - z).
layout::Layout mirror_room(dvec3 tint = {1, 1, 1}) {
    layout::Layout l = plain_room();
    l.portals.push_back(make_mirror("mirror", 0, {0, 1.5, -2}, {0, 0, 1}, 1.0, 2.0, tint));
    return l;
}

dvec3 reflect_point(dvec3 p) { return {p.x, p.y, -4.0 - p.z}; }
dvec3 reflect_dir(dvec3 d) { return {d.x, d.y, -d.z}; }

TEST(TracerMirror, TheSceneKeepsTheKindTheTintAndTheReflection) {
    const Scene scene = prepare_scene(mirror_room({0.5, 0.8, 1.0})).value();
    ASSERT_EQ(scene.portals.size(), 1u);
    const ScenePortal& m = scene.portals[0];
    EXPECT_EQ(m.kind, layout::PortalKind::Mirror);
    EXPECT_EQ(m.target, -1);
    EXPECT_EQ(m.tint, dvec3(0.5, 0.8, 1.0));
    EXPECT_TRUE(m.in_hole);
    EXPECT_EQ(scene.rooms[0].faces[int(layout::Face::NegZ)].holes, std::vector<int>{0});
    expect_point(dvec3(m.reflection * dvec4(0.3, 1.0, 0.5, 1.0)), {0.3, 1.0, -4.5});
}

TEST(TracerMirror, AMirrorShowsTheRoomReflected) {
    const layout::Layout l = mirror_room();
    const Scene scene = prepare_scene(l).value();
    // From (0.2, 1.4, 1) along (0.05, 0.05, -1) the mirror is met at t = 3,
    // (0.35, 1.55, -2). The virtual eye (0.2, 1.4, -5) looks along
    // (0.05, 0.05, 1) and meets the +z wall at t = 7: (0.55, 1.75, 2).
    const TraceHit hit = trace_ray(scene, {0.2, 1.4, 1}, {0.05, 0.05, -1}, 0, 8);
    EXPECT_EQ(hit.id, 1);
    EXPECT_EQ(hit.room, 0);
    EXPECT_EQ(hit.portals_passed, 1);
    expect_point(hit.origin, {0.2, 1.4, -5});
    expect_point(hit.dir, {0.05, 0.05, 1});
    expect_point(hit.point, {0.55, 1.75, 2});
    EXPECT_EQ(hit.normal, dvec3(0, 0, -1));
    const dvec3 wall = shade_by_hand(face_color(l.rooms[0], layout::Face::PosZ), {0, 0, -1}, false);
    expect_point(hit.color, wall);
}

TEST(TracerMirror, EveryRayIntoTheMirrorSeesWhatItsReflectionSeesDirectly) {
    const Scene mirrored = prepare_scene(mirror_room()).value();
    const Scene plain = prepare_scene(plain_room()).value();
    const dvec3 eye{0.3, 1.6, 0.7};
    int in_mirror = 0, beside = 0, on_box = 0;
    for (int i = 0; i <= 40; ++i) {
        for (int j = 0; j <= 40; ++j) {
            const dvec3 dir{-0.6 + 0.0301 * i, -0.7 + 0.0337 * j, -1.0};
            // Where the ray meets the mirror's plane z = -2 (t = 2.7); rays
            // within a micrometre of the mirror's edge may go either way.
            const dvec3 p = eye + 2.7 * dir;
            const double margin = std::min(0.5 - std::abs(p.x), 1.0 - std::abs(p.y - 1.5));
            if (std::abs(margin) < 1e-6) continue;
            const TraceHit got = trace_ray(mirrored, eye, dir, 0, 8);
            if (margin > 0.0) {
                const TraceHit want = trace_ray(plain, reflect_point(eye), reflect_dir(dir), 0, 8);
                ++in_mirror;
                on_box += std::abs(want.point.z - 0.5) < 1e-9;  // the box's face towards the mirror
                EXPECT_EQ(got.id, want.id) << i << "," << j;
                EXPECT_EQ(got.portals_passed, 1) << i << "," << j;
                EXPECT_EQ(want.portals_passed, 0) << i << "," << j;
                expect_point(got.point, want.point, 1e-9);
                expect_point(got.color, want.color);
            } else {
                const TraceHit want = trace_ray(plain, eye, dir, 0, 8);
                ++beside;
                EXPECT_EQ(got.id, want.id);
                EXPECT_EQ(got.portals_passed, 0);
                EXPECT_EQ(got.point, want.point);
                EXPECT_EQ(got.color, want.color);
            }
        }
    }
    EXPECT_GT(in_mirror, 200);
    EXPECT_GT(beside, 200);
    EXPECT_GT(on_box, 0) << "some rays should see the box in the mirror";
}

TEST(TracerMirror, WhatLiesBehindTheMirrorIsNotInIt) {
    // A box outside the room, behind the mirror, on the line of sight of the
    // virtual eye (0, 1.5, -5): the mirror's plane clips it away.
    layout::Layout l = mirror_room();
    l.rooms[0].props.push_back(layout::BoxProp{{-0.3, 1.3, -3.0}, {0.3, 1.7, -2.5}, kRed, {}, {}});
    const TraceHit hit = trace_ray(prepare_scene(l).value(), {0, 1.5, 1}, {0, 0, -1}, 0, 8);
    EXPECT_EQ(hit.portals_passed, 1);
    expect_point(hit.origin, {0, 1.5, -5});
    expect_point(hit.point, {0, 1.5, 2});
    expect_point(hit.color, shade_by_hand(face_color(l.rooms[0], layout::Face::PosZ), {0, 0, -1}, false));
}

TEST(TracerMirror, TheTintMultipliesTheReflection) {
    const dvec3 tint{0.5, 0.8, 0.25};
    const TraceHit clear = trace_ray(prepare_scene(mirror_room()).value(), {0.2, 1.4, 1}, {0.05, 0.05, -1}, 0, 8);
    const TraceHit tinted = trace_ray(prepare_scene(mirror_room(tint)).value(), {0.2, 1.4, 1}, {0.05, 0.05, -1}, 0, 8);
    EXPECT_EQ(tinted.id, clear.id);
    EXPECT_EQ(tinted.point, clear.point);
    expect_point(tinted.color, tint * clear.color);
}

TEST(TracerMirror, AtTheDepthLimitAMirrorShowsTheFill) {
    const Scene scene = prepare_scene(mirror_room({0.5, 0.8, 1.0})).value();
    const TraceHit limit = trace_ray(scene, {0.2, 1.4, 1}, {0.05, 0.05, -1}, 0, 0);
    EXPECT_EQ(limit.id, shading::kFillId);
    EXPECT_EQ(limit.room, 0);
    EXPECT_EQ(limit.portals_passed, 0);
    EXPECT_EQ(limit.color, kFill);  // the fill is not tinted: nothing came back from the mirror
    expect_point(limit.point, {0.35, 1.55, -2});
    EXPECT_EQ(limit.normal, dvec3(0, 0, 1));
    EXPECT_EQ(trace_ray(scene, {0.2, 1.4, 1}, {0.05, 0.05, -1}, 0, 1).id, 1);
}

// Two mirrors 3.6 m wide (|x| ≤ 1.8) on the -z and +z walls of one room.
layout::Layout facing_mirrors(dvec3 far_tint, dvec3 near_tint) {
    layout::Layout l;
    l.rooms.push_back(make_room("hall", {-2, 0, -2}, {2, 3, 2}));
    l.portals.push_back(make_mirror("far", 0, {0, 1.5, -2}, {0, 0, 1}, 3.6, 2.0, far_tint));
    l.portals.push_back(make_mirror("near", 0, {0, 1.5, 2}, {0, 0, -1}, 3.6, 2.0, near_tint));
    return l;
}

TEST(TracerMirror, FacingMirrorsMakeAnEndlessRow) {
    const dvec3 far_tint{0.9, 0.8, 0.7}, near_tint{0.95, 0.9, 0.85};
    const layout::Layout l = facing_mirrors(far_tint, near_tint);
    const Scene scene = prepare_scene(l).value();
    // Straight along -Z from the middle: every reflection meets the other
    // mirror. After k reflections the virtual eye is at z = (-1)^k · 4k and
    // looks at the far mirror when k is even, at the near one when it is odd.
    dvec3 tint_product(1.0);
    for (int depth = 0; depth <= 12; ++depth) {
        const TraceHit hit = trace_ray(scene, {0, 1.5, 0}, {0, 0, -1}, 0, depth);
        EXPECT_EQ(hit.id, shading::kFillId) << depth;
        EXPECT_EQ(hit.portals_passed, depth);
        expect_point(hit.origin, {0, 1.5, (depth % 2 ? -4.0 : 4.0) * depth}, 1e-9);
        expect_point(hit.point, {0, 1.5, depth % 2 ? 2.0 : -2.0}, 1e-9);
        expect_point(hit.color, tint_product * kFill);
        tint_product *= depth % 2 ? near_tint : far_tint;
    }
    // Slanted by 0.09: unfolded, the ray crosses the mirrors' planes at
    // x = 0.18, 0.54, 0.90, 1.26, 1.62 (five reflections, three in the far
    // mirror and two in the near one) and then at x = 1.98, past the
    // mirrors' edge: the +z wall at (1.98, 1.5, 2).
    for (int depth = 0; depth < 5; ++depth) {
        const TraceHit hit = trace_ray(scene, {0, 1.5, 0}, {0.09, 0, -1}, 0, depth);
        EXPECT_EQ(hit.id, shading::kFillId) << depth;
        EXPECT_EQ(hit.portals_passed, depth);
    }
    for (int depth : {5, 6, 64}) {
        const TraceHit hit = trace_ray(scene, {0, 1.5, 0}, {0.09, 0, -1}, 0, depth);
        EXPECT_EQ(hit.id, 1) << depth;
        EXPECT_EQ(hit.portals_passed, 5);
        expect_point(hit.point, {1.98, 1.5, 2}, 1e-9);
        const dvec3 wall = shade_by_hand(face_color(l.rooms[0], layout::Face::PosZ), {0, 0, -1}, false);
        expect_point(hit.color, far_tint * far_tint * far_tint * near_tint * near_tint * wall);
    }
}

TEST(TracerMirror, AnEyeAtContactDistanceSeesOnlyTheReflection) {
    const Scene mirrored = prepare_scene(mirror_room()).value();
    const Scene plain = prepare_scene(plain_room()).value();
    for (double gap : {1e-3, 1e-6}) {
        const TraceHit hit = trace_ray(mirrored, {0, 1.5, -2 + gap}, {0, 0, -1}, 0, 8);
        EXPECT_EQ(hit.id, 1) << gap;
        EXPECT_EQ(hit.portals_passed, 1);
        expect_point(hit.origin, {0, 1.5, -2 - gap});
        expect_point(hit.point, {0, 1.5, 2});
    }
    // A whole view 1 mm from the mirror (both eyes are within its width):
    // each pixel is its reflected ray traced in the room without the mirror.
    TraceDesc desc;
    desc.head.position = {0, 1.5, -1.999};
    desc.eye_width = 16;
    desc.eye_height = 9;
    const image::Image image = trace_frame(mirrored, desc).value();
    EXPECT_EQ(test::count_id(image, 1), 32 * 9);
    for (int eye = 0; eye < 2; ++eye)
        for (int j = 0; j < desc.eye_height; ++j)
            for (int i = 0; i < desc.eye_width; ++i) {
                const PixelRay ray = pixel_ray(desc, eye, i, j);
                const TraceHit want = trace_ray(plain, reflect_point(ray.origin), reflect_dir(ray.dir), 0, 8);
                EXPECT_EQ(test::pixel_rgb(image, eye * desc.eye_width + i, j), test::bytes_of(want.color))
                    << eye << " " << i << "," << j;
            }
}

TEST(TracerMirror, SeenFromBehindAMirrorIsNotThere) {
    const Scene mirrored = prepare_scene(mirror_room()).value();
    const Scene plain = prepare_scene(plain_room()).value();
    // An eye behind the mirror's wall, outside the room, looking in through
    // the mirror's rectangle: (0.05, 1.6) at z = -2, then the +z wall at t = 5.
    const TraceHit hit = trace_ray(mirrored, {0, 1.5, -3}, {0.05, 0.1, 1}, 0, 8);
    EXPECT_EQ(hit.id, 1);
    EXPECT_EQ(hit.portals_passed, 0);
    expect_point(hit.point, {0.25, 2.0, 2});
    // A whole view from behind the wall equals the room's without the mirror.
    TraceDesc desc;
    desc.head.position = {0, 1.5, -2.5};
    desc.head.yaw_deg = 180.0;  // looking along +Z
    desc.eye_width = 24;
    desc.eye_height = 16;
    const image::Image with = trace_frame(mirrored, desc).value(), without = trace_frame(plain, desc).value();
    EXPECT_EQ(with.rgb, without.rgb);
    EXPECT_EQ(with.ids, without.ids);
}

// Room A (at the origin) has mirror mA in its -z wall and door a in its +z
// wall (x in [0.5, 1.5], facing -Z). Room B (ten metres east) has door b in
// its -z wall (x in [11.5, 12.5], facing +Z) and mirror mB in its +z wall
// (x in [11.5, 13.5], facing -Z). M_ab is the translation (11, 0, -4).
layout::Layout mirrors_and_doors(dvec3 tint_a, dvec3 tint_b) {
    layout::Layout l;
    l.rooms.push_back(make_room("a", {-2, 0, -2}, {2, 3, 2}, {0, 0.5, 0.9}));
    l.rooms.push_back(make_room("b", {10, 0, -2}, {14, 3, 2}, {0, 0.2, 0.1}));
    l.portals.push_back(make_mirror("mA", 0, {0, 1.5, -2}, {0, 0, 1}, 1.0, 2.0, tint_a));
    test::add_pair(l, make_portal("a", 0, {1, 1.5, 2}, {0, 0, -1}), make_portal("b", 1, {12, 1.5, -2}, {0, 0, 1}));
    l.portals.push_back(make_mirror("mB", 1, {12.5, 1.5, 2}, {0, 0, -1}, 2.0, 2.0, tint_b));
    return l;
}

TEST(TracerMirror, AMirrorSeenThroughADoor) {
    const dvec3 tint_b{0.5, 0.7, 0.9};
    const layout::Layout l = mirrors_and_doors({1, 1, 1}, tint_b);
    const Scene scene = prepare_scene(l).value();
    expect_point(dvec3(scene.portals[1].transfer * dvec4(0, 0, 0, 1)), {11, 0, -4});
    // From (1, 1.5, 0) along (0.08, 0, 1): door a at (1.16, 1.5, 2); the
    // virtual eye (12, 1.5, -4) meets mB at (12.48, 1.5, 2); reflected, the
    // eye (12, 1.5, 8) looks along (0.08, 0, -1) and meets B's -z wall at
    // (12.8, 1.5, -2), beside door b.
    const TraceHit hit = trace_ray(scene, {1, 1.5, 0}, {0.08, 0, 1}, 0, 8);
    EXPECT_EQ(hit.id, 2);
    EXPECT_EQ(hit.portals_passed, 2);
    expect_point(hit.origin, {12, 1.5, 8});
    expect_point(hit.point, {12.8, 1.5, -2});
    const dvec3 wall = shade_by_hand(face_color(l.rooms[1], layout::Face::NegZ), {0, 0, 1}, false);
    expect_point(hit.color, tint_b * wall);

    const TraceHit limit = trace_ray(scene, {1, 1.5, 0}, {0.08, 0, 1}, 0, 1);
    EXPECT_EQ(limit.id, shading::kFillId);
    EXPECT_EQ(limit.room, 1);
    expect_point(limit.point, {12.48, 1.5, 2});
}

TEST(TracerMirror, ADoorSeenInAMirror) {
    const dvec3 tint_a{0.9, 0.8, 0.6}, tint_b{0.5, 0.7, 0.9};
    const layout::Layout l = mirrors_and_doors(tint_a, tint_b);
    const Scene scene = prepare_scene(l).value();
    // From (0.2, 1.5, 0) along (0.1, 0, -1): mA at (0.4, 1.5, -2). Reflected,
    // the eye (0.2, 1.5, -4) looks along (0.1, 0, 1) and meets door a at
    // (0.8, 1.5, 2); through it, the eye (11.2, 1.5, -8) meets mB at
    // (12.2, 1.5, 2); reflected again, the eye (11.2, 1.5, 12) looks along
    // (0.1, 0, -1) and meets B's -z wall at (12.6, 1.5, -2), beside door b.
    const TraceHit hit = trace_ray(scene, {0.2, 1.5, 0}, {0.1, 0, -1}, 0, 8);
    EXPECT_EQ(hit.id, 2);
    EXPECT_EQ(hit.room, 1);
    EXPECT_EQ(hit.portals_passed, 3);
    expect_point(hit.origin, {11.2, 1.5, 12});
    expect_point(hit.dir, {0.1, 0, -1});
    expect_point(hit.point, {12.6, 1.5, -2});
    const dvec3 wall = shade_by_hand(face_color(l.rooms[1], layout::Face::NegZ), {0, 0, 1}, false);
    expect_point(hit.color, tint_a * tint_b * wall);

    // What the mirror shows is what its virtual eye sees directly.
    const TraceHit direct = trace_ray(scene, {0.2, 1.5, -4}, {0.1, 0, 1}, 0, 8);
    EXPECT_EQ(direct.portals_passed, 2);
    expect_point(direct.point, hit.point);
    expect_point(tint_a * direct.color, hit.color);

    // Depth 2: the door is passed, mB is the limit (the fill, tinted by mA).
    const TraceHit limit = trace_ray(scene, {0.2, 1.5, 0}, {0.1, 0, -1}, 0, 2);
    EXPECT_EQ(limit.id, shading::kFillId);
    EXPECT_EQ(limit.portals_passed, 2);
    expect_point(limit.point, {12.2, 1.5, 2});
    expect_point(limit.color, tint_a * kFill);
}

}  // namespace
}  // namespace impossible::trace
