// --time, --hands and --path FILE --frame K [--fps N] of render and trace
// (cli.md, "Time, hands and lights"): parsed into the frame, the usage errors
// of their combinations, and the frame of a path line as the walker gives it.
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "cli/layout_source.hpp"
#include "cli/view_options.hpp"
#include "common/temp_dir.hpp"
#include "walk/replay.hpp"
#include "walk/walker.hpp"

namespace impossible::cli {
namespace {

// frame_for on a session of its own (it may replace the session by the
// pairing at --path's frame).
render::FrameDesc frame_in(session::Session session, const ViewOptions& o) { return frame_for(session, o); }

ViewOptions parse_path_options(const Args& args, const ViewTables& table = view_options()) {
    return parse_view_options(parse_args(args, 1, table), table);
}

std::string path_usage_error(const Args& args) {
    try {
        parse_path_options(args);
    } catch (const UsageError& e) {
        return e.what();
    }
    return "(no UsageError)";
}

void expect_pose(const math::HeadPose& a, const math::HeadPose& b) {
    EXPECT_EQ(a.position, b.position);
    EXPECT_EQ(a.yaw_deg, b.yaw_deg);
    EXPECT_EQ(a.pitch_deg, b.pitch_deg);
    EXPECT_EQ(a.roll_deg, b.roll_deg);
}

TEST(PathFrameOptions, TimeAndHandsReachTheFrame) {
    const ViewOptions o = parse_path_options({"--time", "-2.5", "--hands", "1,2,3,4,5,6,-1,-2,-3,-4,-5,-6"});
    EXPECT_EQ(o.frame.time, -2.5);
    ASSERT_TRUE(o.frame.hands);
    expect_pose((*o.frame.hands)[0], {{1, 2, 3}, 4, 5, 6});
    expect_pose((*o.frame.hands)[1], {{-1, -2, -3}, -4, -5, -6});
    const ViewOptions none = parse_path_options({});
    EXPECT_EQ(none.frame.time, 0.0);
    EXPECT_FALSE(none.frame.hands);
    EXPECT_FALSE(none.path);
}

TEST(PathFrameOptions, CombinationsAreUsageErrors) {
    for (const char* other : {"--pose", "--room", "--time", "--hands"})
        EXPECT_EQ(path_usage_error({"--path", "p.txt", "--frame", "0", other, "x"}),
                  std::string("--path and ") + other +
                      " exclude each other (line K of the path gives the head, its room, the hands and the time)");
    EXPECT_EQ(path_usage_error({"--frame", "2"}), "--frame needs --path FILE");
    EXPECT_EQ(path_usage_error({"--fps", "30"}), "--fps needs --path FILE");
    EXPECT_EQ(path_usage_error({"--path", "p.txt"}), "--path needs --frame K, the line to draw (from 0)");
    // Before any value is read: a bad value with a bad combination is the usage error.
    EXPECT_EQ(path_usage_error({"--frame", "x", "--time", "nan"}), "--frame needs --path FILE");
}

TEST(PathFrameOptions, BadValuesNameTheirOption) {
    auto input_error = [](const Args& args) -> std::string {
        try {
            parse_path_options(args);
        } catch (const InputError& e) {
            return e.what();
        }
        return "(no InputError)";
    };
    EXPECT_EQ(input_error({"--time", "inf"}), "--time: 'inf' is not a finite number");
    EXPECT_EQ(input_error({"--hands", "1,2,3,4,5,6"}), "--hands: expected 12 comma-separated numbers, got 6");
    EXPECT_EQ(input_error({"--hands", "0,0,0,0,0,0,0,0,0,0,0,-1e8"}),
              "--hands: 0,0,0,0,0,0,0,0,0,0,0,-1e8 has a value beyond 1e7");
    EXPECT_EQ(input_error({"--path", "p", "--frame", "1", "--fps", "1e7"}), "--fps: 1e7 is not in 0.001..1000000");
    EXPECT_EQ(input_error({"--path", "p", "--frame", "1.5"}), "--frame: '1.5' is not an integer");
}

TEST(PathFrameOptions, BenchHasNoFrameOfAPath) {
    // bench walks all of its own --path: render's --path, --frame and --fps are not its view options.
    const std::vector<Option<ViewOptions>> bench =
        without(view_options().own, {"--out", "--ids", "--stats", "--path", "--frame", "--fps"});
    const ViewOptions o = parse_path_options({"--time", "3"}, {bench, view_options().frame});
    EXPECT_EQ(o.frame.time, 3.0);
}

class PathFrameFile : public test::TempDirTest {
protected:
    std::string write(const std::string& text) {
        const std::string path = (dir_ / "walk.txt").string();
        std::ofstream(path) << text;
        return path;
    }
};

// Through the default layout's door (hall to annex), hands on lines 1 and 3.
const char* kDoorWalk =
    "0 1.6 1 0 0 0\n"
    "0 1.6 0.2 10 -5 0   -0.2 1.3 0 0 0 0   0.2 1.3 -0.3 15 20 -5\n"
    "# a comment\n"
    "0 1.6 -0.3 0 0 0\n"
    "0.1 1.5 -0.6 30 0 2   -0.3 1.2 -0.6 5 0 0   0.3 1.4 -1.0 -40 10 0\n";

TEST_F(PathFrameFile, FrameKIsTheWalkersHeadRoomAndHandsAtKOverFps) {
    const layout::Layout layout = load_layout_or_default(std::nullopt);
    const std::string path = write(kDoorWalk);
    const std::vector<layout::PathFrame> lines = value_or_throw(layout::read_path_frames_file(path));
    ASSERT_EQ(lines.size(), 4u);
    walk::Walker walker(layout);
    for (int k = 0; k < 4; ++k) {
        walker.step(lines[k].head);
        const ViewOptions o = parse_path_options({"--path", path, "--frame", std::to_string(k), "--fps", "30"});
        const render::FrameDesc f = frame_in(session::Session(layout), o);
        expect_pose(f.head, math::head_pose_from(walker.position(), walker.rotation()));
        EXPECT_EQ(f.room, walker.room()) << k;
        EXPECT_EQ(f.time, k / 30.0);
        ASSERT_EQ(f.hands.has_value(), lines[k].hands.has_value()) << k;
        if (!f.hands) continue;
        const math::dmat4& w = walker.physical_to_virtual();
        for (int h = 0; h < 2; ++h) {
            const math::HeadPose& physical = (*lines[k].hands)[h];
            const math::HeadPose& got = (*f.hands)[h];
            // Position W · p; orientation W's rotation times the hand's.
            EXPECT_EQ(got.position, math::dvec3(w * math::dvec4(physical.position, 1.0)));
            const math::dmat3 expected = math::dmat3(w) * math::head_rotation(physical);
            const math::dmat3 rotation = math::head_rotation(got);
            for (int c = 0; c < 3; ++c)
                for (int r = 0; r < 3; ++r) EXPECT_NEAR(rotation[c][r], expected[c][r], 1e-12) << k << " " << h;
        }
    }
    // The walk passed the door: the last frames are in the annex.
    EXPECT_EQ(layout.rooms[walker.room()].id, "annex");
    // Default fps: 90.
    EXPECT_EQ(frame_in(session::Session(layout), parse_path_options({"--path", path, "--frame", "3"})).time, 3 / 90.0);
}

TEST_F(PathFrameFile, AFramePastTheLastLineIsAUsageErrorNamingTheCounts) {
    const layout::Layout layout = load_layout_or_default(std::nullopt);
    const std::string path = write(kDoorWalk);
    try {
        frame_in(session::Session(layout), parse_path_options({"--path", path, "--frame", "4"}));
        ADD_FAILURE() << "no UsageError";
    } catch (const UsageError& e) {
        EXPECT_EQ(std::string(e.what()), "--frame 4: " + path + " holds 4 poses (frames 0..3)");
    }
    const std::string one = write("0 1.6 1 0 0 0\n");
    try {
        frame_in(session::Session(layout), parse_path_options({"--path", one, "--frame", "1"}));
        ADD_FAILURE() << "no UsageError";
    } catch (const UsageError& e) {
        EXPECT_EQ(std::string(e.what()), "--frame 1: " + one + " holds 1 pose (frame 0)");
    }
    EXPECT_THROW(frame_in(session::Session(layout),
                          parse_path_options({"--path", (dir_ / "none.txt").string(), "--frame", "0"})),
                 InputError);
}

TEST(PathFrameOptions, VirtualPoseRoundTripsTheRotation) {
    // W: a door's turn of 90 degrees about y and a shift.
    math::dmat4 w(math::rotation_y_deg(90.0));
    w[3] = math::dvec4(1.0, 0.0, -2.0, 1.0);
    for (const math::HeadPose& p : {math::HeadPose{{0.1, 1.2, 0.3}, 30, -20, 10},
                                    math::HeadPose{{0, 1, 0}, -170, 60, -45}, math::HeadPose{{2, 0, 1}, 0, 0, 0}}) {
        const math::HeadPose v = walk::virtual_pose(w, p);
        EXPECT_EQ(v.position, math::dvec3(w * math::dvec4(p.position, 1.0)));
        const math::dmat3 expected = math::dmat3(w) * math::head_rotation(p);
        const math::dmat3 got = math::head_rotation(v);
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) EXPECT_NEAR(got[c][r], expected[c][r], 1e-12);
        EXPECT_NEAR(v.yaw_deg, p.yaw_deg + 90.0 - (p.yaw_deg > 90.0 ? 360.0 : 0.0), 1e-9);
    }
    EXPECT_FALSE(walk::virtual_hands(w, std::nullopt));
}

}  // namespace
}  // namespace impossible::cli

namespace impossible::cli {
namespace {

// The target's id of door `id` in a session's layout ("" for none; a closed
// door is not in it at all).
std::string target_of(const session::Session& s, const std::string& id) {
    for (const layout::Portal& p : s.layout().portals)
        if (p.id == id) return p.target < 0 ? "" : s.layout().portals[static_cast<std::size_t>(p.target)].id;
    return "(closed)";
}

// trace --portal-rays: the pairing frame K started with is the drawn one of
// frame K - 1; at the line where walk makes a change (door_swap's "swap",
// line 34 with the default view options) it is the pairing before it.
TEST(PathFrameOptions, ThePairingAFrameStartedWithIsTheOneBeforeItsChange) {
    const std::string dir = IMPOSSIBLE_SOURCE_DIR "/layouts/";
    const session::Session loaded(load_layout_or_default(dir + "door_swap.json"));
    for (const int k : {0, 33, 34, 35, 60}) {
        const ViewOptions o = parse_path_options({"--path", dir + "door_swap_walk.txt", "--frame", std::to_string(k)});
        session::Session drawn = loaded;
        frame_for(drawn, o);
        const session::Session started = session_frame_started_with(loaded, o);
        // "swap" pairs study_left with garden_door: hall_door and study_right close.
        EXPECT_EQ(target_of(drawn, "study_left"), k >= 34 ? "garden_door" : "hall_door") << k;
        EXPECT_EQ(target_of(drawn, "hall_door"), k >= 34 ? "(closed)" : "study_left") << k;
        EXPECT_EQ(target_of(started, "study_left"), k >= 35 ? "garden_door" : "hall_door") << k;
        EXPECT_EQ(target_of(started, "study_right"), k >= 35 ? "(closed)" : "garden_door") << k;
    }
    // Without --path: the layout's own pairing.
    EXPECT_EQ(target_of(session_frame_started_with(loaded, parse_path_options({})), "study_left"), "hall_door");
}

}  // namespace
}  // namespace impossible::cli
