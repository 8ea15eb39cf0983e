// Windows (layout-format.md, "Mirrors and windows" and "What a pixel shows",
// step 5): the blend of the through and the reflected branch, the id of the
// through branch, the recursion limit, the branch-weight rule of
// scene/shading.hpp (kMinBranchWeight), facing windows, and windows seen
// through doors. Expected hit points are computed by hand in the comments;
// each branch is also traced on its own from its virtual eye.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "trace/trace_test_util.hpp"
#include "trace/tracer.hpp"

namespace impossible::trace {
namespace {

using test::expect_point;
using test::face_color;
using test::kFill;
using test::kTol;
using test::make_mirror;
using test::make_portal;
using test::make_room;
using test::make_window;
using test::shade_by_hand;

// Room A at the origin, room B ten metres east. Window a is in A's -z wall
// (x in [-0.5, 0.5], y in [0.5, 2.5], facing +Z), window b in B's -x wall
// (facing +X). M_ab maps (x, y, z) to (8 - z, y, x) and a direction
// (x, y, z) to (-z, y, x); M_a, the reflection in a's plane, maps z to -4 - z.
layout::Layout window_pair(dvec3 tint, double reflectance) {
    layout::Layout l;
    l.rooms.push_back(make_room("a", {-2, 0, -2}, {2, 3, 2}, {0, 0.5, 0.9}));
    l.rooms.push_back(make_room("b", {10, 0, -2}, {14, 3, 2}, {0, 0.2, 0.1}));
    test::add_pair(l, make_window("a", 0, {0, 1.5, -2}, {0, 0, 1}, 1.0, 2.0, tint, reflectance),
                   make_window("b", 1, {10, 1.5, 0}, {1, 0, 0}, 1.0, 2.0, tint, reflectance));
    return l;
}

// The view from (0, 1.5, 0) along (0.2, 0, -1) meets window a at (0.4, 1.5, -2).
// Through it: the eye (8, 1.5, 0) looks along (1, 0, 0.2) and meets B's +x
// wall at (14, 1.5, 1.2). Reflected: the eye (0, 1.5, -4) looks along
// (0.2, 0, 1) and meets A's +z wall at (1.2, 1.5, 2).
const dvec3 kEye{0, 1.5, 0}, kDir{0.2, 0, -1};

dvec3 through_colour(const layout::Layout& l) {
    return shade_by_hand(face_color(l.rooms[1], layout::Face::PosX), {-1, 0, 0}, false);
}

dvec3 reflected_colour(const layout::Layout& l) {
    return shade_by_hand(face_color(l.rooms[0], layout::Face::PosZ), {0, 0, -1}, false);
}

TEST(TracerWindow, TheSceneKeepsTheKindTheTintAndTheReflectance) {
    const Scene scene = prepare_scene(window_pair({0.9, 0.7, 0.5}, 0.25)).value();
    ASSERT_EQ(scene.portals.size(), 2u);
    for (const ScenePortal& w : scene.portals) {
        EXPECT_EQ(w.kind, layout::PortalKind::Window);
        EXPECT_EQ(w.tint, dvec3(0.9, 0.7, 0.5));
        EXPECT_EQ(w.reflectance, 0.25);
        EXPECT_TRUE(w.in_hole);
    }
    expect_point(dvec3(scene.portals[0].transfer * dvec4(1, 2, 3, 1)), {5, 2, 1});
    expect_point(dvec3(scene.portals[0].reflection * dvec4(1, 2, 3, 1)), {1, 2, -7});
}

TEST(TracerWindow, AWindowBlendsItsTwoBranches) {
    const dvec3 tint{0.9, 0.7, 0.5};
    const double r = 0.25;
    const layout::Layout l = window_pair(tint, r);
    const Scene scene = prepare_scene(l).value();

    // Each branch on its own, from its virtual eye (nothing lies between the
    // virtual eye and the window's partner, so no plane needs to clip).
    const TraceHit through = trace_ray(scene, {8, 1.5, 0}, {1, 0, 0.2}, 1, 8);
    const TraceHit back = trace_ray(scene, {0, 1.5, -4}, {0.2, 0, 1}, 0, 8);
    expect_point(through.point, {14, 1.5, 1.2});
    expect_point(back.point, {1.2, 1.5, 2});
    expect_point(through.color, through_colour(l));
    expect_point(back.color, reflected_colour(l));

    const TraceHit hit = trace_ray(scene, kEye, kDir, 0, 8);
    expect_point(hit.color, (1 - r) * tint * through.color + r * back.color);
    // The id, and the rest of the hit, are the through branch's.
    EXPECT_EQ(hit.id, 2);
    EXPECT_EQ(hit.room, 1);
    EXPECT_EQ(hit.portals_passed, 1);
    expect_point(hit.origin, {8, 1.5, 0});
    expect_point(hit.dir, {1, 0, 0.2});
    expect_point(hit.point, {14, 1.5, 1.2});
    EXPECT_EQ(hit.normal, dvec3(-1, 0, 0));
}

TEST(TracerWindow, BothBranchesAreClippedByThePlanes) {
    // Boxes on both virtual lines of sight, behind the planes: one outside B
    // behind b (the through eye (8, 1.5, 0) would meet it at x = 8.5), one
    // outside A behind a (the reflected eye (0, 1.5, -4) would meet it at
    // z = -3.5). Neither is seen: the pixel is the blend without them.
    const dvec3 tint{0.9, 0.7, 0.5};
    const double r = 0.25;
    layout::Layout l = window_pair(tint, r);
    l.rooms[1].props.push_back(layout::BoxProp{{8.5, 1.3, -0.3}, {9.5, 1.7, 0.5}, {1, 0, 0}, {}, {}});
    l.rooms[0].props.push_back(layout::BoxProp{{-0.3, 1.3, -3.5}, {0.5, 1.7, -2.5}, {1, 0, 0}, {}, {}});
    const TraceHit hit = trace_ray(prepare_scene(l).value(), kEye, kDir, 0, 8);
    EXPECT_EQ(hit.id, 2);
    expect_point(hit.point, {14, 1.5, 1.2});
    expect_point(hit.color, (1 - r) * tint * through_colour(l) + r * reflected_colour(l));
}

TEST(TracerWindow, AtTheDepthLimitAWindowShowsTheFill) {
    const Scene scene = prepare_scene(window_pair({0.9, 0.7, 0.5}, 0.25)).value();
    const TraceHit hit = trace_ray(scene, kEye, kDir, 0, 0);
    EXPECT_EQ(hit.id, shading::kFillId);
    EXPECT_EQ(hit.room, 0);
    EXPECT_EQ(hit.portals_passed, 0);
    EXPECT_EQ(hit.color, kFill);
    expect_point(hit.point, {0.4, 1.5, -2});
    EXPECT_EQ(hit.normal, dvec3(0, 0, 1));
    EXPECT_EQ(trace_ray(scene, kEye, kDir, 0, 1).id, 2);
}

TEST(TracerWindow, AThroughBranchCutByWeightGivesTheIdOfTheLimit) {
    // A black tint: the through branch's weight is 0, so it shows the fill
    // (times its factor 0) and the id is 255; the reflection is still seen.
    const double r = 0.25;
    const layout::Layout l = window_pair({0, 0, 0}, r);
    const TraceHit hit = trace_ray(prepare_scene(l).value(), kEye, kDir, 0, 8);
    EXPECT_EQ(hit.id, shading::kFillId);
    EXPECT_EQ(hit.room, 0);
    EXPECT_EQ(hit.portals_passed, 0);
    expect_point(hit.point, {0.4, 1.5, -2});
    expect_point(hit.color, r * reflected_colour(l));

    // Reflectance 1: the same, with the whole reflection.
    const layout::Layout mirror_like = window_pair({1, 1, 1}, 1.0);
    const TraceHit all_back = trace_ray(prepare_scene(mirror_like).value(), kEye, kDir, 0, 8);
    EXPECT_EQ(all_back.id, shading::kFillId);
    expect_point(all_back.color, reflected_colour(mirror_like));
}

TEST(TracerWindow, AReflectionBelowTheMinimumWeightShowsTheFill) {
    const double cut = ::impossible::shading::kMinBranchWeight;
    // r = 0.001 < 1/256: the reflected branch is not followed and shows the fill.
    {
        const layout::Layout l = window_pair({1, 1, 1}, 0.001);
        const TraceHit hit = trace_ray(prepare_scene(l).value(), kEye, kDir, 0, 8);
        EXPECT_EQ(hit.id, 2);
        expect_point(hit.color, 0.999 * through_colour(l) + 0.001 * kFill);
    }
    // Exactly at the minimum the branch is followed; just below it is not.
    {
        const layout::Layout l = window_pair({1, 1, 1}, cut);
        const TraceHit hit = trace_ray(prepare_scene(l).value(), kEye, kDir, 0, 8);
        expect_point(hit.color, (1 - cut) * through_colour(l) + cut * reflected_colour(l));
    }
    {
        const double r = std::nextafter(cut, 0.0);
        const layout::Layout l = window_pair({1, 1, 1}, r);
        const TraceHit hit = trace_ray(prepare_scene(l).value(), kEye, kDir, 0, 8);
        expect_point(hit.color, (1 - r) * through_colour(l) + r * kFill);
    }
}

TEST(TracerWindow, WeightsMultiplyAlongTheView) {
    // A mirror in A's +z wall (|x| ≤ 0.5, facing -Z). From (0, 1.5, 0) along
    // (0.04, 0, 1) it is met at (0.08, 1.5, 2); reflected, the eye (0, 1.5, 4)
    // looks along (0.04, 0, -1) and meets window a at (0.24, 1.5, -2).
    // Through a: the eye (4, 1.5, 0) looks along (1, 0, 0.04) and meets B's +x
    // wall at (14, 1.5, 0.4). Reflected in a: the eye (0, 1.5, -8) meets the
    // mirror again at (0.4, 1.5, 2), and then A's -z wall at (0.56, 1.5, -2),
    // beside the window.
    const double r = 0.03;
    for (double grey : {1.0, 0.1}) {
        layout::Layout l = window_pair({1, 1, 1}, r);
        l.portals.push_back(make_mirror("m", 0, {0, 1.5, 2}, {0, 0, -1}, 1.0, 2.0, {grey, grey, grey}));
        const TraceHit hit = trace_ray(prepare_scene(l).value(), kEye, {0.04, 0, 1}, 0, 8);
        EXPECT_EQ(hit.id, 2);
        EXPECT_EQ(hit.portals_passed, 2);
        expect_point(hit.point, {14, 1.5, 0.4});
        const dvec3 a_wall = shade_by_hand(face_color(l.rooms[0], layout::Face::NegZ), {0, 0, 1}, false);
        if (grey == 1.0) {
            // Weight of the reflection 0.03 ≥ 1/256: followed.
            expect_point(hit.color, (1 - r) * through_colour(l) + r * a_wall);
        } else {
            // 0.1 · 0.03 = 0.003 < 1/256: the fill, though r alone would pass.
            expect_point(hit.color, grey * ((1 - r) * through_colour(l) + r * kFill));
        }
    }
}

// Two windows of one room facing each other and linked to each other: the
// view through the far one comes out of the near one (M is the translation
// (0, 0, 4)) and sees the far one again.
layout::Layout facing_windows(dvec3 tint, double reflectance) {
    layout::Layout l;
    l.rooms.push_back(make_room("hall", {-2, 0, -2}, {2, 3, 2}));
    test::add_pair(l, make_window("far", 0, {0, 1.5, -2}, {0, 0, 1}, 1.0, 2.0, tint, reflectance),
                   make_window("near", 0, {0, 1.5, 2}, {0, 0, -1}, 1.0, 2.0, tint, reflectance));
    return l;
}

TEST(TracerWindow, FacingWindowsBranchUntilTheWeightRuleStops) {
    // Straight along -Z every branch meets a window again. With r = 0.5 and
    // max(tint) = 1 both branches weigh half their parent: a view k portals
    // deep weighs 2^-k, so the views at depth 8 are followed and their
    // branches (2^-9 < 1/256) show the fill. Each path to a fill carries the
    // factors (1 - r) · tint or r, one per window, so the pixel is
    // fill · ((1 - r) · tint + r)^k with k = min(max_depth, 9); the id path
    // (through, through, ...) ends with 255 after min(max_depth, 8) portals.
    const dvec3 tint{1, 0.5, 0.25};
    const double r = 0.5;
    const Scene scene = prepare_scene(facing_windows(tint, r)).value();
    for (int depth : {0, 1, 3, 8, 9, 10, 64}) {
        const TraceHit hit = trace_ray(scene, {0, 1.5, 0}, {0, 0, -1}, 0, depth);
        const int k = std::min(depth, 9);
        const dvec3 per_level = (1 - r) * tint + r;
        const dvec3 want{kFill.x * std::pow(per_level.x, k), kFill.y * std::pow(per_level.y, k),
                         kFill.z * std::pow(per_level.z, k)};
        EXPECT_EQ(hit.id, shading::kFillId) << depth;
        EXPECT_EQ(hit.portals_passed, std::min(depth, 8)) << depth;
        expect_point(hit.color, want);
    }
}

TEST(TracerWindow, FacingWindowsAtDepth64FinishQuickly) {
    // The worst case of the weight rule (r = 0.5, clear glass: every view
    // splits in two of half its weight) over a whole frame at depth 64.
    // Without the rule a pixel could have 2^64 views; with it, at most 2^9
    // end in a fill. (About 0.1 s; the bound leaves room for a loaded machine.)
    const Scene scene = prepare_scene(facing_windows({1, 1, 1}, 0.5)).value();
    TraceDesc desc;
    desc.head.position = {0, 1.5, 0};
    desc.eye_width = 160;
    desc.eye_height = 90;
    desc.max_depth = 64;
    const auto start = std::chrono::steady_clock::now();
    const image::Image image = trace_frame(scene, desc).value();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("  facing windows, depth 64, 160x90 per eye: %.3f s\n", seconds);
    EXPECT_LT(seconds, 20.0);
    EXPECT_GT(test::count_id(image, shading::kFillId), 0);
    EXPECT_GT(test::count_id(image, 1), 0);
    EXPECT_EQ(test::count_id(image, 0), 0);
}

TEST(TracerWindow, AWindowSeenThroughADoor) {
    // Room H (index 2), far west, has door h in its -z wall (x in
    // [-18.5, -17.5], facing +Z), paired with door d in A's +z wall (|x| ≤ 0.5,
    // facing -Z): M_hd is the translation (18, 0, 4). From (-18, 1.5, 1)
    // along (0.05, 0, -1): door h at (-17.85, 1.5, -2); the virtual eye
    // (0, 1.5, 5) meets window a at (0.35, 1.5, -2). Through a: the eye
    // (3, 1.5, 0) looks along (1, 0, 0.05) and meets B's +x wall at
    // (14, 1.5, 0.55). Reflected in a: the eye (0, 1.5, -9) looks along
    // (0.05, 0, 1) and meets A's +z wall at (0.55, 1.5, 2), beside door d.
    const dvec3 tint{0.9, 0.7, 0.5};
    const double r = 0.25;
    layout::Layout l = window_pair(tint, r);
    l.rooms.push_back(make_room("h", {-20, 0, -2}, {-16, 3, 2}, {0, 0.7, 0.3}));
    test::add_pair(l, make_portal("h", 2, {-18, 1.5, -2}, {0, 0, 1}), make_portal("d", 0, {0, 1.5, 2}, {0, 0, -1}));
    const Scene scene = prepare_scene(l).value();
    expect_point(dvec3(scene.portals[2].transfer * dvec4(0, 0, 0, 1)), {18, 0, 4});

    const dvec3 eye{-18, 1.5, 1}, dir{0.05, 0, -1};
    const TraceHit hit = trace_ray(scene, eye, dir, 2, 8);
    EXPECT_EQ(hit.id, 2);  // B, the through branch's
    EXPECT_EQ(hit.portals_passed, 2);
    expect_point(hit.origin, {3, 1.5, 0});
    expect_point(hit.point, {14, 1.5, 0.55});
    expect_point(hit.color, (1 - r) * tint * through_colour(l) + r * reflected_colour(l));

    // The window is the second portal: at depth 1 it shows the fill.
    const TraceHit limit = trace_ray(scene, eye, dir, 2, 1);
    EXPECT_EQ(limit.id, shading::kFillId);
    EXPECT_EQ(limit.room, 0);
    EXPECT_EQ(limit.portals_passed, 1);
    expect_point(limit.point, {0.35, 1.5, -2});
    EXPECT_EQ(limit.color, kFill);
}

TEST(TracerWindow, SeenFromBehindAWindowIsNotThere) {
    // An eye behind A's -z wall looking in through window a's rectangle.
    const TraceHit hit =
        trace_ray(prepare_scene(window_pair({0.9, 0.7, 0.5}, 0.25)).value(), {0, 1.5, -3}, {0, 0, 1}, 0, 8);
    EXPECT_EQ(hit.id, 1);
    EXPECT_EQ(hit.portals_passed, 0);
    expect_point(hit.point, {0, 1.5, 2});
}

}  // namespace
}  // namespace impossible::trace
