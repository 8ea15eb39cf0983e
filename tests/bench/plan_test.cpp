// keep_first_portals: closing portals for the bench's portal sweep keeps
// pairs whole, mirrors (which have no target) and renumbers targets; the
// sweep's N/all-steps item draws every door pass; the light sweep's
// baselines; the volume sweep's ways to draw a volume.
#include <gtest/gtest.h>

#include "bench/plan.hpp"
#include "cli/errors.hpp"

namespace impossible::bench {
namespace {

// --sweep as parse_bench_options reads it: the items parsed before any layout.
void with_sweep(BenchOptions& o, const std::string& sweep) {
    o.sweep = sweep;
    o.sweep_items = parse_sweep(sweep);
}

// A 4 x 3 x 4 m room, the start in its middle.
layout::Layout one_room() {
    layout::Layout l;
    l.rooms.resize(1);
    l.rooms[0].min = {-2, 0, -2};
    l.rooms[0].max = {2, 3, 2};
    l.start.room = 0;
    l.start.position = {0, 1.6, 0};
    return l;
}

layout::Portal portal(const std::string& id, int target, layout::PortalKind kind) {
    layout::Portal p;
    p.id = id;
    p.room = 0;
    p.target = target;
    p.kind = kind;
    return p;
}

TEST(BenchPlan, KeepFirstPortalsKeepsMirrorsAndWholePairs) {
    layout::Layout l;
    l.rooms.resize(1);
    using layout::PortalKind;
    l.portals = {portal("mirror", -1, PortalKind::Mirror), portal("a", 3, PortalKind::Door),
                 portal("w", 4, PortalKind::Window),       portal("b", 1, PortalKind::Door),
                 portal("x", 2, PortalKind::Window),       portal("late_mirror", -1, PortalKind::Mirror)};
    // The first four: the mirror and the door pair; w's partner is beyond.
    const layout::Layout four = keep_first_portals(l, 4);
    ASSERT_EQ(four.portals.size(), 3u);
    EXPECT_EQ(four.portals[0].id, "mirror");
    EXPECT_EQ(four.portals[0].target, -1);
    EXPECT_EQ(four.portals[1].id, "a");
    EXPECT_EQ(four.portals[1].target, 2);
    EXPECT_EQ(four.portals[2].id, "b");
    EXPECT_EQ(four.portals[2].target, 1);
    // All of them.
    const layout::Layout all = keep_first_portals(l, 6);
    ASSERT_EQ(all.portals.size(), 6u);
    for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(all.portals[i].target, l.portals[i].target);
    // None.
    EXPECT_TRUE(keep_first_portals(l, 0).portals.empty());
}

// "N/all-steps" keeps the same N portals with every door pass
// (FrameDesc::portal_steps off), beside "N" with the cheaper steps.
TEST(BenchPlan, AllStepsItemDrawsEveryDoorPass) {
    layout::Layout l = one_room();
    using layout::PortalKind;
    l.portals = {portal("a", 1, PortalKind::Door), portal("b", 0, PortalKind::Door)};
    BenchOptions o;
    with_sweep(o, "portals:0,2,2/all-steps");
    const BenchPlan plan = plan_bench(session::Session(l), o);
    ASSERT_EQ(plan.configs.size(), 4u);  // base + 3
    EXPECT_EQ(plan.configs[2].name, "portals=2");
    EXPECT_TRUE(plan.configs[2].frame.portal_steps);
    EXPECT_EQ(plan.configs[3].name, "portals=2/all-steps");
    EXPECT_FALSE(plan.configs[3].frame.portal_steps);
    EXPECT_EQ(plan.sessions[plan.configs[3].layout_variant].layout().portals.size(), 2u);
    EXPECT_TRUE(plan.sessions[plan.configs[1].layout_variant].layout().portals.empty());
    EXPECT_THROW(with_sweep(o, "portals:2/some-steps"), cli::InputError);
}

// "N/naive" draws N lights per room without the portal tests, "N/one-part"
// with every lit room in one part (FrameDesc::split_light_draws off),
// "N/no-cache" without the light cache, beside "N" as users see it.
TEST(BenchPlan, LightItemsPickTheBaselines) {
    layout::Layout l = one_room();
    BenchOptions o;
    with_sweep(o, "lights:2,2/naive,2/one-part,2/no-cache");
    const BenchPlan plan = plan_bench(session::Session(l), o);
    ASSERT_EQ(plan.configs.size(), 5u);  // base + 4
    for (size_t k = 1; k < 5; ++k) {
        const BenchConfig& c = plan.configs[k];
        EXPECT_EQ(plan.sessions[static_cast<size_t>(c.layout_variant)].layout().rooms[0].lights.size(), 2u);
        EXPECT_EQ(c.frame.naive_lights, k == 2) << c.name;
        EXPECT_EQ(c.frame.split_light_draws, k != 3) << c.name;
        EXPECT_EQ(c.frame.light_cache, k != 4) << c.name;
    }
    EXPECT_EQ(plan.configs[3].name, "lights=2/one-part");
    EXPECT_THROW(with_sweep(o, "lights:fixed/one-part"), cli::InputError);
    EXPECT_THROW(with_sweep(o, "lights:2/two-parts"), cli::InputError);
}

TEST(BenchPlan, VolumeItemsPickTheWaysToDrawAVolume) {
    layout::Layout l = one_room();
    BenchOptions o;
    with_sweep(o, "volumes:split,whole-target,one-variant,none");
    const BenchPlan plan = plan_bench(session::Session(l), o);
    ASSERT_EQ(plan.configs.size(), 5u);  // base + 4
    EXPECT_EQ(plan.configs[2].name, "volumes=whole-target");
    const bool split[] = {true, true, false, true}, pieces[] = {true, false, true, true};
    for (size_t k = 0; k < 4; ++k) {
        const BenchConfig& c = plan.configs[k + 1];
        EXPECT_EQ(c.frame.split_volume_draws, split[k]) << c.name;
        EXPECT_EQ(c.frame.volume_pieces, pieces[k]) << c.name;
        EXPECT_EQ(c.layout_variant != 0, k == 3) << c.name;  // none: the layout without its volumes
    }
    EXPECT_THROW(with_sweep(o, "volumes:pieces"), cli::InputError);
}

}  // namespace
}  // namespace impossible::bench
