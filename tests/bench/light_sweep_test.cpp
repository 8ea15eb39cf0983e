// The lighting sweeps of bench (issue 27): with_lights puts N lights in every
// room, strictly inside it, or returns the layout under the fixed light; the
// plan makes one configuration per item and refuses what it cannot measure.
#include <gtest/gtest.h>

#include "bench/light_sweep.hpp"
#include "bench/plan.hpp"
#include "cli/errors.hpp"
#include "common/layouts.hpp"
#include "layout/room_shape.hpp"

namespace impossible::bench {
namespace {

// --sweep as parse_bench_options reads it: the items parsed before any layout.
void set_sweep(BenchOptions& o, const std::string& sweep) {
    o.sweep = sweep;
    o.sweep_items = parse_sweep(sweep);
}

layout::Layout two_rooms() {
    layout::Layout l;
    l.rooms.resize(2);
    l.rooms[0].min = {-2, 0, -2};
    l.rooms[0].max = {2, 3, 2};
    l.rooms[1].min = {10, -1, 0};
    l.rooms[1].max = {12, 1.5, 8};
    l.rooms[1].lights.resize(3);  // replaced
    return l;
}

TEST(BenchLightSweep, NLightsStrictlyInsideEveryRoomSummingToFour) {
    for (int n : {0, 1, 8, 32}) {
        const layout::Layout lit = with_lights(two_rooms(), n);
        EXPECT_EQ(lit.lighting, layout::Lighting::Lights);
        for (const layout::Room& room : lit.rooms) {
            ASSERT_EQ(room.lights.size(), static_cast<std::size_t>(n));
            double sum = 0.0;
            for (const layout::Light& light : room.lights) {
                for (int a = 0; a < 3; ++a) {
                    EXPECT_GT(light.position[a], room.min[a]);
                    EXPECT_LT(light.position[a], room.max[a]);
                }
                sum += light.intensity;
            }
            if (n > 0) {
                EXPECT_NEAR(sum, 4.0, 1e-12);
            }
        }
    }
}

TEST(BenchLightSweep, FixedDropsTheLights) {
    layout::Layout l = two_rooms();
    l.lighting = layout::Lighting::Lights;
    const layout::Layout fixed = with_lights(l, -1);
    EXPECT_EQ(fixed.lighting, layout::Lighting::Fixed);
    for (const layout::Room& room : fixed.rooms) EXPECT_TRUE(room.lights.empty());
}

TEST(BenchLightSweep, PlanItems) {
    layout::Layout l = two_rooms();
    l.start.room = 0;
    l.start.position = {0, 1.6, 0};
    BenchOptions o;
    set_sweep(o, "lights:fixed,0,8");
    const BenchPlan plan = plan_bench(session::Session(l), o);
    ASSERT_EQ(plan.configs.size(), 4u);  // base + 3
    ASSERT_EQ(plan.sessions.size(), 4u);
    EXPECT_EQ(plan.sessions[plan.configs[1].layout_variant].layout().lighting, layout::Lighting::Fixed);
    EXPECT_EQ(plan.sessions[plan.configs[3].layout_variant].layout().rooms[0].lights.size(), 8u);
    EXPECT_THROW(set_sweep(o, "lights:x"), cli::InputError);
    // The light depth needs a lit layout; then each item sets View::light_depth.
    set_sweep(o, "light-depth:0,2");
    EXPECT_THROW(plan_bench(session::Session(l), o), cli::InputError);
    l.lighting = layout::Lighting::Lights;
    const BenchPlan depths = plan_bench(session::Session(l), o);
    ASSERT_EQ(depths.configs.size(), 3u);
    EXPECT_EQ(depths.configs[2].frame.light_depth, 2);
    EXPECT_THROW(set_sweep(o, "light-depth:17"), cli::InputError);
    set_sweep(o, "shadow-size:0,256");
    const BenchPlan sizes = plan_bench(session::Session(l), o);
    ASSERT_EQ(sizes.configs.size(), 3u);
    EXPECT_FALSE(sizes.configs[1].frame.shadows);
    EXPECT_EQ(sizes.configs[2].frame.shadow_map_size, 256);
}

// Prism rooms (issue 23): an L and a turned square keep the grid's lights
// over their floors (none in the L's notch), 5 cm from their walls,
// summing to 4, and boxes on their floors only.
TEST(BenchLightSweep, PrismRoomsKeepLightsAndBoxesOnTheirFloors) {
    layout::Layout l;
    l.rooms.push_back(test::prism_room("l", {{0, 0}, {6, 0}, {6, 3}, {3, 3}, {3, 6}, {0, 6}}, 0.0, 2.5));
    l.rooms.push_back(test::prism_room("turned", {{0, -3}, {3, 0}, {0, 3}, {-3, 0}}, 0.0, 2.5));
    l.start.room = 0;
    l.start.position = {1, 1.6, 1};
    const layout::Layout lit = with_lights(l, 16);
    for (const layout::Room& room : lit.rooms) {
        ASSERT_GT(room.lights.size(), 0u) << room.id;
        EXPECT_LT(room.lights.size(), 16u) << room.id;
        double sum = 0.0;
        for (const layout::Light& light : room.lights) {
            EXPECT_TRUE(inside_floor(room, light.position)) << room.id;
            sum += light.intensity;
        }
        EXPECT_NEAR(sum, 4.0, 1e-12) << room.id;
    }
    BenchOptions o;
    set_sweep(o, "boxes:100");
    const BenchPlan plan = plan_bench(session::Session(l), o);
    ASSERT_EQ(plan.sessions.size(), 2u);
    for (const layout::Room& room : plan.sessions[1].layout().rooms) {
        ASSERT_GT(room.props.size(), 0u);
        EXPECT_LT(room.props.size(), 100u);
        for (const layout::Prop& prop : room.props) {
            const auto& box = std::get<layout::BoxProp>(prop);
            for (const double x : {box.min.x, box.max.x})
                for (const double z : {box.min.z, box.max.z}) EXPECT_TRUE(layout::room_contains(room, {x, 0.0, z}));
            EXPECT_FALSE(box.min.x < 3.0 && box.max.x > 3.0 && box.min.z < 3.0 && box.max.z > 3.0) << "over the corner";
        }
    }
}

}  // namespace
}  // namespace impossible::bench
