// bench --path: each line of the walk is measured at its virtual head and
// room, at time k / fps, with the hands of an 18-number line mapped by the
// walker (as `render --path FILE --frame k` draws it).
#include <fstream>

#include <gtest/gtest.h>

#include "bench/plan.hpp"
#include "cli/layout_source.hpp"
#include "common/temp_dir.hpp"
#include "walk/replay.hpp"

namespace impossible::bench {
namespace {

using BenchWalk = test::TempDirTest;

TEST_F(BenchWalk, EachLineHasItsTimeAndHands) {
    const layout::Layout layout = cli::load_layout_or_default(std::nullopt);
    const std::string path = (dir_ / "walk.txt").string();
    std::ofstream(path) << "0 1.6 1 0 0 0\n"
                           "0 1.6 0.2 0 0 0  -0.2 1.3 0 0 0 0  0.2 1.3 -0.3 0 0 0\n"
                           "0 1.6 -0.3 0 0 0\n";
    BenchOptions o;
    o.path = path;
    o.fps = 30.0;
    const std::vector<BenchPose> poses = bench_poses(session::Session(layout), o);
    ASSERT_EQ(poses.size(), 3u);
    const layout::PathFrames read = layout::read_path_frames_file(path);
    ASSERT_TRUE(read) << read.error();
    const std::vector<layout::PathFrame>& lines = *read;
    for (std::size_t k = 0; k < 3; ++k) {
        math::View expected;
        walk::set_replayed_view(expected, layout, lines, k, 30.0);
        EXPECT_EQ(poses[k].head.position, expected.head.position) << k;
        EXPECT_EQ(poses[k].room, expected.room) << k;
        EXPECT_EQ(poses[k].time, k / 30.0) << k;
        ASSERT_EQ(poses[k].hands.has_value(), k == 1) << k;
    }
    EXPECT_EQ((*poses[1].hands)[1].position, math::dvec3(0.2, 1.3, -0.3));  // no door passed yet: W = identity
    // Without --path: the one pose at --time with --hands.
    BenchOptions still;
    still.view.frame.time = 4.5;
    still.view.frame.hands = std::array<math::HeadPose, 2>{};
    const std::vector<BenchPose> one = bench_poses(session::Session(layout), still);
    ASSERT_EQ(one.size(), 1u);
    EXPECT_EQ(one[0].time, 4.5);
    EXPECT_TRUE(one[0].hands);
}

}  // namespace
}  // namespace impossible::bench
