// `impossible walk` with 18-number path lines, --fps and moving props
// (cli.md, "Time, hands and lights"), through the built program.
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "hostile_util.hpp"

namespace impossible::hostile {
namespace {

// "hall" (x -2..2) whose east door leads to "annex", far away (x 10..14); a
// crate in hall slides 2 m east in 1 s: its centre, at x 0.95, passes the
// door at t = 0.525 s.
const char* const kWalkFramesLayout = R"({
  "format": "impossible-layout", "version": 1, "name": "crate",
  "play_area": {"min": [-2, -2], "max": [2, 2]},
  "start": {"room": "hall", "position": [0, 1.6, 1], "yaw_deg": 0},
  "rooms": [
    {"id": "hall", "min": [-2, 0, -2], "max": [2, 3, 2],
     "props": [{"id": "crate", "box": {"min": [0.85, 0.6, -0.1], "max": [1.05, 0.8, 0.1]},
                "motion": {"path": [[0, 0, 0, 0], [1, 2, 0, 0]]}}]},
    {"id": "annex", "min": [10, 0, -2], "max": [14, 3, 2]}
  ],
  "portals": [
    {"id": "hall_east", "room": "hall", "center": [2, 1.1, 0], "normal": [-1, 0, 0], "width": 1, "height": 2.2,
     "target": "annex_west"},
    {"id": "annex_west", "room": "annex", "center": [10, 1.1, 0], "normal": [1, 0, 0], "width": 1, "height": 2.2,
     "target": "hall_east"}
  ]
})";

std::vector<nlohmann::json> walk_frames_lines(const std::string& out) {
    std::vector<nlohmann::json> lines;
    std::istringstream in(out);
    for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
    return lines;
}

TEST_F(Hostile, WalkReadsEighteenNumberLinesAndNamesTheHandsRooms) {
    spit(dir_ / "crate.json", kWalkFramesLayout);
    // The head 0.3 m before the door; the right hand 0.3 m through it, the
    // left past the wall beside it; then a line without hands.
    spit(dir_ / "hands.txt",
         "1.7 1.6 0 -90 0 0\t2.3 1.6 1.5 -90 0 0 2.3 1.2 0 -90 0 0\r\n"
         "# a comment\n"
         "1.7 1.6 0 -90 0 0\n");
    const Outcome r = run("$BIN walk crate.json --path hands.txt");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::vector<nlohmann::json> lines = walk_frames_lines(r.out);
    ASSERT_EQ(lines.size(), 2u) << r.out;
    EXPECT_EQ(lines[0]["room"], "hall");
    EXPECT_EQ(lines[0]["hands"], nlohmann::json::array({"hall", "annex"})) << r.out;
    EXPECT_FALSE(lines[1].contains("hands")) << r.out;
    // Every line names the moving crate's room; at 90 fps both are at t < 0.525.
    EXPECT_EQ(lines[0]["props"], nlohmann::json({{"crate", "hall"}})) << r.out;
    EXPECT_EQ(lines[1]["props"], nlohmann::json({{"crate", "hall"}})) << r.out;
    // Without a moving prop, a line without hands is as before: five keys.
    const Outcome plain = run("$BIN walk lay.json --path hands.txt");
    ASSERT_EQ(plain.status, 0) << plain.err;
    const std::vector<nlohmann::json> plain_lines = walk_frames_lines(plain.out);
    ASSERT_EQ(plain_lines.size(), 2u);
    EXPECT_TRUE(plain_lines[0].contains("hands"));
    EXPECT_EQ(plain_lines[1].size(), 5u) << plain.out;
}

// Line k is at time k / fps: the crate is in annex from line 48 at the
// default 90 fps (47 / 90 < 0.525 < 48 / 90), from line 6 at --fps 10.
TEST_F(Hostile, WalkFpsSetsTheTimeOfEachLine) {
    spit(dir_ / "crate.json", kWalkFramesLayout);
    std::string still;
    for (int k = 0; k < 60; ++k) still += "0 1.6 1 0 0 0\n";
    spit(dir_ / "still.txt", still);
    for (const auto& [options, first_annex] :
         {std::pair<std::string, int>{"", 48}, {"--fps 90", 48}, {"--fps 10", 6}, {"--fps=1e1", 6}}) {
        const Outcome r = run("$BIN walk crate.json --path still.txt " + options);
        ASSERT_EQ(r.status, 0) << options << ": " << r.err;
        const std::vector<nlohmann::json> lines = walk_frames_lines(r.out);
        ASSERT_EQ(lines.size(), 60u) << options;
        for (int k = 0; k < 60; ++k)
            EXPECT_EQ(lines[static_cast<std::size_t>(k)]["props"]["crate"], k < first_annex ? "hall" : "annex")
                << options << ", line " << k;
    }
}

TEST_F(Hostile, WalkRefusesBadFpsAndOtherFieldCounts) {
    spit(dir_ / "p.txt", "0 1.6 1 0 0 0\n");
    for (const char* value : {"0", "-90", "nan", "inf", "abc", "1e7", "0.0001", "''"})
        expect_refused(run(std::string("$BIN walk lay.json --path p.txt --fps ") + value), 1, "--fps: ");
    expect_refused(run("$BIN walk lay.json --path p.txt --fps"), 2, "--fps");
    for (const char* value : {"0.001", "1000000", "+30"}) {
        const Outcome r = run(std::string("$BIN walk lay.json --path p.txt --fps ") + value);
        EXPECT_EQ(r.status, 0) << value << ": " << r.err;
    }
    spit(dir_ / "seven.txt", "0 1.6 1 0 0 0\n0 1.6 1 0 0 0 1\n");
    const Outcome seven = run("$BIN walk lay.json --path seven.txt");
    expect_refused(seven, 1,
                   "seven.txt:2: expected 6 or 18 numbers (X Y Z YAW PITCH ROLL of the head, then of the left and the "
                   "right hand), found 7 fields");
    EXPECT_EQ(seven.out, "");
    spit(dir_ / "hand.txt", "0 1.6 1 0 0 0 0 1 0 0 0 0 0 1 0 nan 0 0\n");
    expect_refused(run("$BIN walk lay.json --path hand.txt"), 1,
                   "hand.txt:1: right hand YAW: 'nan' is not a finite number");
}

}  // namespace
}  // namespace impossible::hostile
