// `impossible trace --portal-rays N` (cli.md, trace): the portals the pixel
// rays reach, printed on standard error, with --path FILE --frame K for the
// pairing frame K started with; layouts/door_swap.json and its walk, whose
// change "swap" walk makes at line 34 (the head in the study, looking at the
// desk).
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "app/commands.hpp"
#include "app/run_main_capture.hpp"
#include "common/temp_dir.hpp"

namespace impossible::app {
namespace {

using TraceRun = testing::Ran;
using testing::run;

const std::string kLayouts = IMPOSSIBLE_SOURCE_DIR "/layouts/";

TraceRun trace_frame(const test::TempDir& dir, int frame, const std::string& step = "1") {
    return run({"trace", kLayouts + "door_swap.json", "--path", kLayouts + "door_swap_walk.txt", "--frame",
                std::to_string(frame), "--size", "48x32", "--threads", "1", "--portal-rays", step, "--out",
                (dir.path() / "t.png").string()});
}

TEST(TracePortalRays, PrintsThePortalsTheRaysReachAtAFrameOfAWalk) {
    const test::TempDir dir("portal_rays");
    // Walking to the study's door: the hall's door ahead.
    TraceRun r = trace_frame(dir, 30);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "portal_rays: hall_door\n");
    // Line 34: walk makes "swap" there, so none of its four doors is reached
    // with the pairing the frame started with.
    r = trace_frame(dir, 34);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "portal_rays:\n");
    // Turned round in the study: the door it came in by, now the garden's.
    r = trace_frame(dir, 100, "3");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "portal_rays: study_left\n");
}

TEST(TracePortalRays, WithoutTheOptionNothingIsPrintedAndZeroIsAnError) {
    const test::TempDir dir("portal_rays_none");
    const TraceRun r =
        run({"trace", kLayouts + "door_swap.json", "--size", "48x32", "--out", (dir.path() / "t.png").string()});
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_NE(trace_frame(dir, 30, "0").status, 0);
}

}  // namespace
}  // namespace impossible::app
