// `render --path FILE --frame K` and `trace --path FILE --frame K` draw
// exactly what `--pose <the walked head> --room <its room> --time K/fps
// --hands <the walked hands>` draws (cli.md, "Time, hands and lights"), byte
// for byte, through a door that turns the walk by 90 degrees.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "base/format.hpp"
#include "common/temp_dir.hpp"
#include "layout/layout.hpp"
#include "layout/path_file.hpp"
#include "walk/walker.hpp"

namespace impossible {
namespace {

namespace fs = std::filesystem;

const std::string kTurningDoorLayout = IMPOSSIBLE_SOURCE_DIR "/layouts/rotated.json";

// Lines 1 and 3 have hands; the right hand of line 1 is through the door
// before the head, line 2 passes the door (a 90-degree turn).
const char* kTurningWalk =
    "0.05 1.6 1.0 0 0 0\n"
    "0.05 1.6 0.4 5 -10 0   -0.25 1.2 0.3 0 0 0   0.2 1.35 -0.1 10 -30 5\n"
    "0.05 1.6 -0.3 0 0 0\n"
    "0.1 1.6 -0.7 10 5 2   -0.2 1.3 -0.9 0 0 0   0.25 1.35 -1.1 -20 15 0\n";

int run_in(const fs::path& dir, const std::string& args) {
    const std::string command = "cd '" + dir.string() + "' && '" IMPOSSIBLE_BINARY "' " + args + " 2>err.txt";
    const int raw = std::system(command.c_str());
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

std::string file_bytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string pose_text(const math::HeadPose& p) {
    std::string s;
    for (double v : {p.position.x, p.position.y, p.position.z, p.yaw_deg, p.pitch_deg, p.roll_deg})
        s += (s.empty() ? "" : ",") + format_number(v);
    return s;
}

// The options that say by hand what line `k` of the walk says: the walker's
// virtual head, its room, the time k / fps and each physical hand mapped by W.
std::string explicit_options(const layout::Layout& layout, const std::vector<layout::PathFrame>& lines, int k,
                             double fps) {
    walk::Walker walker(layout);
    for (int i = 0; i <= k; ++i) walker.step(lines[i].head);
    std::string options = "--pose " + pose_text(math::head_pose_from(walker.position(), walker.rotation())) +
                          " --room " + layout.rooms[walker.room()].id + " --time " + format_number(k / fps);
    if (!lines[k].hands) return options;
    const math::dmat4& w = walker.physical_to_virtual();
    std::string hands;
    for (const math::HeadPose& hand : *lines[k].hands) {
        const math::dvec3 position(w * math::dvec4(hand.position, 1.0));
        hands += (hands.empty() ? "" : ",") +
                 pose_text(math::head_pose_from(position, math::dmat3(w) * math::head_rotation(hand)));
    }
    return options + " --hands " + hands;
}

class PathFrameRender : public test::TempDirTest {};

TEST_F(PathFrameRender, AFrameOfAPathIsItsWalkedPoseRoomTimeAndHands) {
    std::ofstream(dir_ / "walk.txt") << kTurningWalk;
    const layout::LoadResult loaded = layout::load_layout_file(kTurningDoorLayout);
    ASSERT_TRUE(loaded.layout) << "rotated.json";
    const layout::Layout& layout = *loaded.layout;
    const layout::PathFrames read = layout::read_path_frames_file((dir_ / "walk.txt").string());
    ASSERT_TRUE(read) << read.error();
    const std::vector<layout::PathFrame>& lines = *read;
    ASSERT_EQ(lines.size(), 4u);
    const std::string common = " '" + kTurningDoorLayout + "' --size 96x54 ";
    for (const char* command : {"render", "trace"}) {
        for (int k : {1, 2, 3}) {
            const std::string fps = k == 3 ? " --fps 24" : "";
            const std::string by_path = std::string(command) + common +
                                        "--out a.png --ids a-ids.png --path walk.txt --frame " + std::to_string(k) +
                                        fps;
            ASSERT_EQ(run_in(dir_, by_path), 0) << by_path << ": " << file_bytes(dir_ / "err.txt");
            const std::string by_hand = std::string(command) + common + "--out b.png --ids b-ids.png " +
                                        explicit_options(layout, lines, k, k == 3 ? 24.0 : 90.0);
            ASSERT_EQ(run_in(dir_, by_hand), 0) << by_hand << ": " << file_bytes(dir_ / "err.txt");
            EXPECT_EQ(file_bytes(dir_ / "a.png"), file_bytes(dir_ / "b.png")) << by_path << "\n" << by_hand;
            EXPECT_EQ(file_bytes(dir_ / "a-ids.png"), file_bytes(dir_ / "b-ids.png")) << by_path << "\n" << by_hand;
            if (k == 1) {
                // Line 1's right hand reaches through the door ahead of the head: drawn.
                const std::string without_hands = by_hand.substr(0, by_hand.find(" --hands "));
                ASSERT_EQ(run_in(dir_, without_hands), 0) << without_hands;
                EXPECT_NE(file_bytes(dir_ / "a.png"), file_bytes(dir_ / "b.png")) << without_hands;
            }
            fs::rename(dir_ / "a.png", dir_ / ("frame" + std::to_string(k) + ".png"));
            fs::rename(dir_ / "a-ids.png", dir_ / ("frame" + std::to_string(k) + "-ids.png"));
        }
        // Not the same view thrice: the walk turned at the door.
        EXPECT_NE(file_bytes(dir_ / "frame1.png"), file_bytes(dir_ / "frame3.png")) << command;
        EXPECT_NE(file_bytes(dir_ / "frame1-ids.png"), file_bytes(dir_ / "frame3-ids.png")) << command;
    }
}

}  // namespace
}  // namespace impossible
