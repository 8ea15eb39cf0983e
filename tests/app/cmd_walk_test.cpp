// `impossible walk`: the path file and the JSON lines (cli.md), through
// run_walk / run_walk_stream with layouts built in code.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/cmd_walk.hpp"
#include "common/temp_dir.hpp"
#include "walk/walk_test_layouts.hpp"
#include "walk/walker.hpp"

namespace impossible::app {
namespace {

using walk::testing::doorway;

struct Replay {
    int status = -1;
    std::string out;
    std::string err;
};

Replay replay(const layout::Layout& l, const std::string& path_text, const std::string& name = "walk.txt") {
    std::istringstream in(path_text);
    std::ostringstream out, err;
    Replay r;
    r.status = run_walk_stream(session::Session(l), in, name, out, err);
    r.out = out.str();
    r.err = err.str();
    return r;
}

std::vector<nlohmann::json> parse_lines(const std::string& text) {
    std::vector<nlohmann::json> lines;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) lines.push_back(nlohmann::json::parse(line));
    return lines;
}

TEST(RunWalk, FirstLineMatchesTheContractByteForByte) {
    const Replay r = replay(doorway(), "0 1.6 1 0 0 0\n");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(r.out,
              "{\"frame\":0,\"room\":\"hall\",\"teleports\":[],\"position\":[0,1.6,1],"
              "\"forward\":[0,0,-1]}\n");
}

TEST(RunWalk, WalksThroughTheDoorwayAndBack) {
    const std::string path =
        "# a walk east through the doorway and back\n"
        "\n"
        "0 1.6 0 -90 0 0\n"
        "  1.5\t1.6 0 -90 0 0\r\n"
        "   # an indented comment\n"
        "2.5 1.6 0 -90 0 0\n"
        "1.0 1.6 0 90 0 0\n"
        "1.0 1.6 0 90 0 0";  // no final newline
    const Replay r = replay(doorway(), path);
    ASSERT_EQ(r.status, 0) << r.err;
    const auto lines = parse_lines(r.out);
    ASSERT_EQ(lines.size(), 5u);
    for (std::size_t k = 0; k < lines.size(); ++k) {
        EXPECT_EQ(lines[k]["frame"], k);
        ASSERT_EQ(lines[k].size(), 5u);  // exactly the five fields
        ASSERT_TRUE(lines[k]["teleports"].is_array());
        ASSERT_EQ(lines[k]["position"].size(), 3u);
        ASSERT_EQ(lines[k]["forward"].size(), 3u);
    }
    EXPECT_EQ(lines[0]["room"], "hall");
    EXPECT_EQ(lines[1]["teleports"], nlohmann::json::array());
    EXPECT_EQ(lines[2]["room"], "annex");
    EXPECT_EQ(lines[2]["teleports"], nlohmann::json::array({"hall_east"}));
    EXPECT_EQ(lines[2]["position"], nlohmann::json::array({2.5, 1.6, 0}));
    EXPECT_EQ(lines[2]["forward"], nlohmann::json::array({1, 0, 0}));  // yaw -90 looks along +X
    EXPECT_EQ(lines[3]["room"], "hall");
    EXPECT_EQ(lines[3]["teleports"], nlohmann::json::array({"annex_west"}));
    EXPECT_EQ(lines[3]["forward"], nlohmann::json::array({-1, 0, 0}));
    EXPECT_EQ(lines[4]["teleports"], nlohmann::json::array());
}

TEST(RunWalk, NumbersRoundTrip) {
    // A skewed pair gives positions with all their digits.
    const layout::Layout l = walk::testing::skewed_pair();
    const math::PortalRect& a = l.portals[0].rect;
    std::ostringstream path;
    path.precision(17);
    for (double d : {0.4, -0.4}) {
        const math::dvec3 p = a.center + d * a.normal;
        path << p.x << ' ' << p.y << ' ' << p.z << " 12.5 -3 7\n";
    }
    const Replay r = replay(l, path.str());
    ASSERT_EQ(r.status, 0) << r.err;
    const auto lines = parse_lines(r.out);
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[1]["teleports"], nlohmann::json::array({"a"}));
    EXPECT_EQ(lines[1]["room"], "r1");
    // Replaying the same poses in code gives the very same doubles (17
    // significant digits in the path file read back exactly).
    walk::Walker w(l);
    for (double d : {0.4, -0.4}) w.step(math::HeadPose{a.center + d * a.normal, 12.5, -3.0, 7.0});
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(lines[1]["position"][k].get<double>(), w.position()[k]);
        EXPECT_EQ(lines[1]["forward"][k].get<double>(), w.forward()[k]);
    }
}

TEST(RunWalk, MalformedLinesGiveOneErrorAndNoOutput) {
    const struct {
        const char* text;
        const char* expected;
    } cases[] = {
        {"0 1.6 1 0 0 0\n0 1.6 1 0 0\n", "walk.txt:2: expected 6 or 18 numbers"},
        {"0 1.6 1 0 0 0 9\n", "walk.txt:1: expected 6 or 18 numbers"},
        {"# c\n\n0 1.6 x 0 0 0\n", "walk.txt:3: Z: 'x' is not a finite number"},
        {"0,1.6,1,0,0,0\n", "walk.txt:1: expected 6 or 18 numbers"},
        {"0 1.6 1 nan 0 0\n", "walk.txt:1: YAW: 'nan' is not a finite number"},
        {"0 1.6 1 0 inf 0\n", "walk.txt:1: PITCH: 'inf' is not a finite number"},
        {"0 1.6 1e400 0 0 0\n", "walk.txt:1: Z: '1e400' is not a finite number"},
        {"0 1.6 1 0 0 0x10\n", "walk.txt:1: ROLL: '0x10' is hexadecimal: write numbers in decimal"},
        {"1e7 1.6 1 0 0 0\n", "walk.txt:1: X: 1e7 is out of range"},
        {"0 1.6 1 0 0 -2e6\n", "walk.txt:1: ROLL: -2e6 is out of range"},
        {"0 1.6 1 0 0 0 # trailing comment\n", "walk.txt:1: expected 6 or 18 numbers"},
    };
    for (const auto& c : cases) {
        const Replay r = replay(doorway(), c.text);
        EXPECT_EQ(r.status, 1) << c.text;
        EXPECT_EQ(r.out, "") << c.text;
        EXPECT_EQ(r.err.rfind(c.expected, 0), 0u) << "got: " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
    // A leading '+' and exponents are numbers.
    EXPECT_EQ(replay(doorway(), "+0 1.6e0 1 -0 0 0\n").status, 0);
}

// Like plan, bench and preview (issue 26): a path without poses is refused.
TEST(RunWalk, APathWithoutPosesIsRefused) {
    const Replay r = replay(doorway(), "# nothing\n\n");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "walk.txt: the path file holds no poses\n");
}

TEST(RunWalk, ReadsAFileAndReportsMissingOnes) {
    const test::TempDir dir("cmd_walk_test");
    const std::string file = (dir / "path.txt").string();
    {
        std::ofstream f(file);
        f << "0 1.6 1 0 0 0\n0 1.6 0.5 0 0 0\n";
    }
    std::ostringstream out, err;
    EXPECT_EQ(run_walk(session::Session(doorway()), file, out, err), 0);
    EXPECT_EQ(parse_lines(out.str()).size(), 2u);
    EXPECT_EQ(err.str(), "");

    std::ostringstream out2, err2;
    EXPECT_EQ(run_walk(session::Session(doorway()), (dir / "missing.txt").string(), out2, err2), 1);
    EXPECT_EQ(out2.str(), "");
    EXPECT_NE(err2.str().find("missing.txt: does not exist"), std::string::npos) << err2.str();

    std::ostringstream out3, err3;
    EXPECT_EQ(run_walk(session::Session(doorway()), dir.path().string(), out3, err3), 1);
    EXPECT_EQ(out3.str(), "");
    EXPECT_NE(err3.str().find("directory"), std::string::npos) << err3.str();
}

}  // namespace
}  // namespace impossible::app
