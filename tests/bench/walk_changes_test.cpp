// bench --path through a layout's changes: each line is drawn with the
// pairing in force at it, as `render --path FILE --frame k` draws it
// (session::replay_to), with the seen test on the bench's view options.
#include <fstream>

#include <gtest/gtest.h>

#include "bench/plan.hpp"
#include "changes/change_layouts.hpp"
#include "cli/layout_source.hpp"
#include "common/temp_dir.hpp"
#include "session/walk_driver.hpp"

namespace impossible::bench {
namespace {

using BenchWalkChanges = test::TempDirTest;

TEST_F(BenchWalkChanges, EachLineIsDrawnWithThePairingInForceAtIt) {
    const session::Session session(changes::testing::door_swap());
    const std::string path = (dir_ / "walk.txt").string();
    // Into the study looking back west at study_west (the change waits),
    // then east (it is made), then a step back west (no door: closed).
    std::ofstream(path) << "0 1.6 0 -90 0 0\n3 1.6 0 90 0 0\n3 1.6 0 -90 0 0\n1.5 1.6 0 -90 0 0\n";
    BenchOptions o;
    o.path = path;
    std::vector<session::Session> stages;
    const std::vector<BenchPose> poses = bench_poses(session, o, &stages);
    ASSERT_EQ(poses.size(), 4u);
    ASSERT_EQ(stages.size(), 1u);
    EXPECT_EQ(stages[0].layout().portals.size(), 2u);
    const layout::PathFrames frames = layout::read_path_frames_file(path);
    ASSERT_TRUE(frames) << frames.error();
    for (std::size_t k = 0; k < poses.size(); ++k) {
        EXPECT_EQ(poses[k].stage, k < 2 ? 0 : 1) << k;
        math::View view;  // render's defaults, as the bench's
        const session::Session drawn = session::replay_to(session, view, *frames, k, layout::kDefaultPathFps);
        EXPECT_EQ(drawn.layout().portals.size(), k < 2 ? 4u : 2u) << k;
        EXPECT_EQ(poses[k].head.position, view.head.position) << k;
        EXPECT_EQ(poses[k].room, view.room) << k;
    }
    EXPECT_EQ(poses[3].room, 1);  // still the study: study_west is closed
    // The plan draws stage 1 with the variants of the paired layout.
    BenchPlan plan = plan_bench(session, o);
    add_stages(plan, stages, o);
    ASSERT_EQ(plan.stages.size(), 1u);
    ASSERT_EQ(plan.stages[0].size(), plan.sessions.size());
    EXPECT_EQ(plan.session_of(0, 0).layout().portals.size(), 4u);
    EXPECT_EQ(plan.session_of(0, 1).layout().portals.size(), 2u);
    // --portals N: the first N portals of each stage's layout, without changes
    // (their indices are the loaded layout's).
    o.portals = 2;
    BenchPlan kept = plan_bench(session, o);
    add_stages(kept, stages, o);
    EXPECT_TRUE(kept.session_of(0, 0).layout().changes.empty());
    EXPECT_EQ(kept.session_of(0, 0).layout().portals.size(), 2u);  // hall_east and study_west
    EXPECT_EQ(kept.session_of(0, 1).layout().portals.size(), 2u);  // hall_east and garden_west
    EXPECT_EQ(kept.session_of(0, 1).layout().portals[1].id, "garden_west");
}

TEST_F(BenchWalkChanges, TheBenchsViewOptionsPlaceTheEyesOfTheSeenTest) {
    // In the study 0.3 m from study_west, looking south: the door's edge
    // lies 31 degrees off the view axis, inside render's default field of
    // view (the change waits) and outside --fov 10 (it is made).
    const session::Session session(changes::testing::door_swap());
    const std::string path = (dir_ / "look.txt").string();
    std::ofstream(path) << "0 1.6 0 -90 0 0\n2.3 1.6 0 180 0 0\n";
    BenchOptions o;
    o.path = path;
    std::vector<session::Session> stages;
    EXPECT_EQ(bench_poses(session, o, &stages)[1].stage, 0);
    EXPECT_TRUE(stages.empty());
    o.view.frame.fov_y_deg = 10.0;
    EXPECT_EQ(bench_poses(session, o, &stages)[1].stage, 1);
    EXPECT_EQ(stages.size(), 1u);
}

TEST_F(BenchWalkChanges, TheDoorSwapWalkChangesItsStageWhereWalkMakesTheSwap) {
    const std::string base = std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/door_swap";
    const session::Session session(cli::load_layout_or_default(base + ".json"));
    BenchOptions o;
    o.path = base + "_walk.txt";
    std::vector<session::Session> stages;
    const std::vector<BenchPose> poses = bench_poses(session, o, &stages);
    ASSERT_EQ(stages.size(), 1u);
    const layout::PathFrames frames = layout::read_path_frames_file(*o.path);
    ASSERT_TRUE(frames) << frames.error();
    session::WalkDriver driver(session);
    for (std::size_t k = 0; k < poses.size(); ++k) {
        const bool made = !driver.step((*frames)[k].head, std::nullopt, k / 90.0).changes.empty();
        if (made) {
            EXPECT_EQ(poses[k].stage, 1) << k;
            EXPECT_EQ(poses[k - 1].stage, 0) << k;
        }
        EXPECT_EQ(poses[k].room, driver.walker().room()) << k;
    }
    EXPECT_EQ(poses.back().stage, 1);
}

}  // namespace
}  // namespace impossible::bench
