// The budget of portal passes per ray tree (docs/bounded-work.md): every
// door, mirror and window branch a pixel sample's tree follows counts one,
// in the order the tree is followed (a window's reflected branch first);
// once the budget is spent, every further portal shows the fill colour (id
// 255 on the id's path), as at the depth limit. A tree that needs no more
// than the budget is traced exactly as without one.
#include <gtest/gtest.h>

#include <climits>
#include <filesystem>

#include "trace/trace_test_util.hpp"
#include "trace/tracer.hpp"

namespace impossible::trace {
namespace {

using test::expect_point;
using test::kFill;
using test::make_mirror;
using test::make_room;
using test::make_window;

constexpr int kNoBudget = INT_MAX;

// Two mirrors 3.6 m wide on the -z and +z walls of one room, as in
// tracer_mirror_test.cpp: straight along -Z every reflection meets the other.
layout::Layout budget_facing_mirrors(dvec3 far_tint, dvec3 near_tint) {
    layout::Layout l;
    l.rooms.push_back(make_room("hall", {-2, 0, -2}, {2, 3, 2}));
    l.portals.push_back(make_mirror("far", 0, {0, 1.5, -2}, {0, 0, 1}, 3.6, 2.0, far_tint));
    l.portals.push_back(make_mirror("near", 0, {0, 1.5, 2}, {0, 0, -1}, 3.6, 2.0, near_tint));
    return l;
}

// Two facing windows (1 × 2 m) on the -z and +z walls, as in
// tracer_window_test.cpp.
layout::Layout budget_facing_windows(dvec3 tint, double reflectance) {
    layout::Layout l;
    l.rooms.push_back(make_room("hall", {-2, 0, -2}, {2, 3, 2}));
    test::add_pair(l, make_window("far", 0, {0, 1.5, -2}, {0, 0, 1}, 1.0, 2.0, tint, reflectance),
                   make_window("near", 0, {0, 1.5, 2}, {0, 0, -1}, 1.0, 2.0, tint, reflectance));
    return l;
}

layout::Layout budget_layout_file(const char* name) {
    const layout::LoadResult loaded = layout::load_layout_file(std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/" + name);
    EXPECT_TRUE(loaded.errors.empty()) << name;
    return loaded.layout.value();
}

TraceDesc budget_start_view(const layout::Layout& l, int width, int height) {
    TraceDesc desc;
    desc.head.position = l.start.position;
    desc.head.yaw_deg = l.start.yaw_deg;
    desc.room = l.start.room;
    desc.eye_width = width;
    desc.eye_height = height;
    return desc;
}

TEST(TracerBudget, FacingMirrorsShowTheFillWhereTheBudgetIsSpent) {
    // Straight along -Z a ray passes one mirror per level, one pass each:
    // with a budget of b passes it ends on the (b + 1)th mirror, exactly as
    // at a depth limit of b, and the fill is counted as the budget's.
    const Scene scene = prepare_scene(budget_facing_mirrors({0.9, 0.8, 0.7}, {0.95, 0.9, 0.85})).value();
    const dvec3 eye{0, 1.5, 0}, dir{0, 0, -1};
    for (int budget : {0, 1, 2, 5, 12}) {
        const TraceHit cut = trace_ray(scene, eye, dir, 0, RayLimits{64, budget});
        const TraceHit deep = trace_ray(scene, eye, dir, 0, RayLimits{budget, kNoBudget});
        EXPECT_EQ(cut.id, shading::kFillId) << budget;
        EXPECT_EQ(cut.portals_passed, budget);
        EXPECT_EQ(cut.passes, budget);
        EXPECT_EQ(cut.budget_fills, 1);
        EXPECT_EQ(cut.color, deep.color) << budget;  // the fill, tinted by the mirrors it lies in
        EXPECT_EQ(cut.point, deep.point);
        EXPECT_EQ(deep.budget_fills, 0);
    }
    // At the depth limit the fill is the limit's, even with the budget spent
    // there too; a budget one larger is not reached.
    EXPECT_EQ(trace_ray(scene, eye, dir, 0, RayLimits{64, 64}).budget_fills, 0);
    const TraceHit free = trace_ray(scene, eye, dir, 0, RayLimits{64, kNoBudget});
    const TraceHit within = trace_ray(scene, eye, dir, 0, RayLimits{64, 65});
    EXPECT_EQ(within.passes, 64);
    EXPECT_EQ(within.budget_fills, 0);
    EXPECT_EQ(within.color, free.color);
}

TEST(TracerBudget, TheTreeIsCutInTheOrderItIsFollowed) {
    // Facing windows, r = 0.5: every window splits the view in two (weights
    // 2^-k), so at depth 8 the tree follows 2 · (1 + 2 + ... + 128) = 510
    // branches. With a budget of 3 (the reflected branch first): the root
    // window counts its reflection (1), the window behind it its reflection
    // (2), the next its reflection (3); the window met there (depth 3) finds
    // the budget spent and shows the fill. Then the through branches counted
    // back up the tree (4, 5, 6) each meet one more window, also the fill.
    // Four fills, with the factors r³, r² (1 - r) t, r (1 - r) t, (1 - r) t;
    // the id's path (through at the root) ends on the window one level in.
    const dvec3 tint{1, 0.6, 0.3};
    const double r = 0.5;
    const Scene scene = prepare_scene(budget_facing_windows(tint, r)).value();
    const dvec3 eye{0, 1.5, 0}, dir{0, 0, -1};
    const TraceHit free = trace_ray(scene, eye, dir, 0, RayLimits{8, kNoBudget});
    EXPECT_EQ(free.passes, 510);
    EXPECT_EQ(free.budget_fills, 0);

    const TraceHit cut = trace_ray(scene, eye, dir, 0, RayLimits{8, 3});
    EXPECT_EQ(cut.passes, 6);
    EXPECT_EQ(cut.budget_fills, 4);
    EXPECT_EQ(cut.id, shading::kFillId);
    EXPECT_EQ(cut.portals_passed, 1);
    const dvec3 t = (1 - r) * tint;
    expect_point(cut.color, kFill * (r * r * r + r * r * t + r * t + t));

    // A budget the tree does not reach changes nothing, to the bit. A
    // window is checked once and then counts both its branches, as the
    // rasteriser's are: the last window (the id's path at depth 7) is met
    // after 508 passes, so a budget of 509 is not reached either.
    for (int budget : {509, 510, 511, 10'000}) {
        const TraceHit within = trace_ray(scene, eye, dir, 0, RayLimits{8, budget});
        EXPECT_EQ(within.color, free.color) << budget;
        EXPECT_EQ(within.id, free.id);
        EXPECT_EQ(within.passes, 510);
        EXPECT_EQ(within.budget_fills, 0);
    }
    // With 508 that window shows the fill instead of its two branches.
    const TraceHit short_one = trace_ray(scene, eye, dir, 0, RayLimits{8, 508});
    EXPECT_EQ(short_one.passes, 508);
    EXPECT_EQ(short_one.budget_fills, 1);
    EXPECT_EQ(short_one.portals_passed, 7);
    EXPECT_NE(short_one.color, free.color);
}

TEST(TracerBudget, AFrameShowsTheFillExactlyWhereTheTreesRanOut) {
    // The corridor of layouts/corridor.json: doors only, so each pixel's tree
    // is one path. A pixel whose path passes at most 2 doors is traced as
    // without a budget; any other ends on its third door with the fill.
    const layout::Layout l = budget_layout_file("corridor.json");
    const Scene scene = prepare_scene(l).value();
    TraceDesc desc = budget_start_view(l, 48, 27);
    desc.max_depth = 250;
    desc.max_portal_passes = kNoBudget;
    TraceStats none;
    const image::Image free = trace_frame(scene, desc, &none).value();
    EXPECT_EQ(none.budget_rays, 0);
    desc.max_portal_passes = 2;
    desc.threads = 1;
    TraceStats stats;
    const image::Image cut = trace_frame(scene, desc, &stats).value();
    long deeper = 0;
    for (int eye = 0; eye < 2; ++eye) {
        for (int j = 0; j < desc.eye_height; ++j) {
            for (int i = 0; i < desc.eye_width; ++i) {
                const PixelRay ray = pixel_ray(desc, eye, i, j);
                const int passes = trace_ray(scene, ray.origin, ray.dir, desc.room, RayLimits{250, kNoBudget}).passes;
                const int x = eye * desc.eye_width + i;
                if (passes <= 2) {
                    EXPECT_EQ(test::pixel_id(cut, x, j), test::pixel_id(free, x, j)) << x << "," << j;
                    EXPECT_EQ(test::pixel_rgb(cut, x, j), test::pixel_rgb(free, x, j)) << x << "," << j;
                    continue;
                }
                ++deeper;
                EXPECT_EQ(test::pixel_id(cut, x, j), shading::kFillId) << x << "," << j;
                EXPECT_EQ(test::pixel_rgb(cut, x, j), test::bytes_of(kFill)) << x << "," << j;
            }
        }
    }
    EXPECT_GT(deeper, 0);
    EXPECT_LT(deeper, 2L * desc.eye_width * desc.eye_height);
    EXPECT_EQ(stats.budget_rays, deeper);
    EXPECT_EQ(stats.budget_fills, deeper);  // one cut per path
    // Neither the image nor the counts depend on the threads.
    for (int threads : {2, 5}) {
        desc.threads = threads;
        TraceStats again;
        const image::Image many = trace_frame(scene, desc, &again).value();
        EXPECT_EQ(many.rgb, cut.rgb) << threads;
        EXPECT_EQ(many.ids, cut.ids) << threads;
        EXPECT_EQ(again.budget_rays, stats.budget_rays) << threads;
        EXPECT_EQ(again.budget_fills, stats.budget_fills) << threads;
    }
}

TEST(TracerBudget, TheDefaultBudgetLeavesTheLayoutsAsTheyWere) {
    // Every layout of layouts/ at its start, at the default depth and at 250:
    // the default budget is not reached, and the frame is the one without it.
    int layouts = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts")) {
        if (entry.path().extension() != ".json") continue;
        ++layouts;
        const std::string name = entry.path().filename().string();
        const layout::Layout l = budget_layout_file(name.c_str());
        const Scene scene = prepare_scene(l).value();
        for (int depth : {8, 250}) {
            TraceDesc desc = budget_start_view(l, 32, 18);
            desc.max_depth = depth;
            TraceStats stats;
            const image::Image budgeted = trace_frame(scene, desc, &stats).value();
            desc.max_portal_passes = kNoBudget;
            const image::Image free = trace_frame(scene, desc).value();
            EXPECT_EQ(stats.budget_fills, 0) << name << " " << depth;
            EXPECT_EQ(budgeted.rgb, free.rgb) << name << " " << depth;
            EXPECT_EQ(budgeted.ids, free.ids) << name << " " << depth;
        }
    }
    EXPECT_GE(layouts, 10);
}

TEST(TracerBudget, ANegativeBudgetIsAnError) {
    const Scene scene = prepare_scene(budget_facing_mirrors({1, 1, 1}, {1, 1, 1})).value();
    TraceDesc desc;
    desc.head.position = {0, 1.5, 0};
    desc.eye_width = 4;
    desc.eye_height = 4;
    desc.max_portal_passes = -1;
    const Result<image::Image> image = trace_frame(scene, desc);
    ASSERT_FALSE(image);
    EXPECT_NE(image.error().find("max_portal_passes"), std::string::npos) << image.error();
}

}  // namespace
}  // namespace impossible::trace
