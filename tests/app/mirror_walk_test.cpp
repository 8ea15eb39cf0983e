// `impossible walk` on a layout file with a door, a mirror and a window pair
// (tests/data/layouts/mirrors_windows.json): only the door teleports; walking
// through the mirror's or the window's plane keeps the room (layout-format.md,
// "Head, eyes and walking", last paragraph).
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/cmd_walk.hpp"
#include "layout/layout.hpp"

namespace impossible::app {
namespace {

layout::Layout mirrors_windows() {
    const layout::LoadResult r =
        layout::load_layout_file(std::string(IMPOSSIBLE_TEST_DATA) + "/layouts/mirrors_windows.json");
    std::string errors;
    for (const layout::Diagnostic& d : r.errors) errors += d.str() + "\n";
    EXPECT_TRUE(r.layout.has_value()) << errors;
    return r.layout.value_or(layout::Layout{});
}

std::vector<nlohmann::json> walk(const layout::Layout& l, const std::string& path) {
    std::istringstream in(path);
    std::ostringstream out, err;
    EXPECT_EQ(run_walk_stream(session::Session(l), in, "walk.txt", out, err), 0) << err.str();
    EXPECT_EQ(err.str(), "");
    std::vector<nlohmann::json> lines;
    std::istringstream text(out.str());
    for (std::string line; std::getline(text, line);) lines.push_back(nlohmann::json::parse(line));
    return lines;
}

TEST(WalkMirrors, TheMirrorsPlaneIsPassedLikeAWall) {
    // North through the mirror in the hall's -z wall (z = -2), slowly, then
    // back in one fast step.
    const auto lines = walk(mirrors_windows(),
                            "0 1.6 0 0 0 0\n"
                            "0 1.6 -1.95 0 0 0\n"
                            "0 1.6 -2 0 0 0\n"
                            "0 1.6 -2.05 0 0 0\n"
                            "0 1.6 -30 0 0 0\n"
                            "0 1.6 1 0 0 0\n");
    ASSERT_EQ(lines.size(), 6u);
    for (const auto& line : lines) {
        EXPECT_EQ(line["room"], "hall") << line.dump();
        EXPECT_EQ(line["teleports"], nlohmann::json::array()) << line.dump();
    }
    EXPECT_EQ(lines[3]["position"], nlohmann::json::array({0, 1.6, -2.05}));
    EXPECT_EQ(lines[4]["position"], nlohmann::json::array({0, 1.6, -30}));
    EXPECT_EQ(lines[4]["forward"], nlohmann::json::array({0, 0, -1}));
}

TEST(WalkMirrors, TheWindowsPlaneIsPassedLikeAWall) {
    // West through the hall's window (x = -2), which shows the annex: the
    // head stays in the hall, where it is, however fast it goes.
    const auto lines = walk(mirrors_windows(),
                            "0 1.5 0 90 0 0\n"
                            "-1.9 1.5 0 90 0 0\n"
                            "-2.1 1.5 0 90 0 0\n"
                            "-25 1.5 0.2 90 0 0\n"
                            "1 1.5 0 90 0 0\n");
    ASSERT_EQ(lines.size(), 5u);
    for (const auto& line : lines) {
        EXPECT_EQ(line["room"], "hall") << line.dump();
        EXPECT_EQ(line["teleports"], nlohmann::json::array()) << line.dump();
    }
    EXPECT_EQ(lines[2]["position"], nlohmann::json::array({-2.1, 1.5, 0}));
    EXPECT_EQ(lines[3]["position"], nlohmann::json::array({-25, 1.5, 0.2}));
}

TEST(WalkMirrors, TheDoorStillTeleportsAndTheAnnexWindowKeepsTheAnnex) {
    // East through the door into the annex, on through the annex's window
    // (x = 5, partner of the hall's), and back through the door.
    const auto lines = walk(mirrors_windows(),
                            "0 1.6 0 -90 0 0\n"
                            "2.5 1.6 0 -90 0 0\n"
                            "5.5 1.6 0 -90 0 0\n"
                            "9 1.6 0 -90 0 0\n"
                            "1 1.6 0 90 0 0\n");
    ASSERT_EQ(lines.size(), 5u);
    EXPECT_EQ(lines[1]["room"], "annex");
    EXPECT_EQ(lines[1]["teleports"], nlohmann::json::array({"hall_east"}));
    for (int k : {2, 3}) {
        EXPECT_EQ(lines[k]["room"], "annex") << lines[k].dump();
        EXPECT_EQ(lines[k]["teleports"], nlohmann::json::array()) << lines[k].dump();
    }
    EXPECT_EQ(lines[3]["position"], nlohmann::json::array({9, 1.6, 0}));
    // Back west in one step: through the annex window's plane (from behind)
    // and the door.
    EXPECT_EQ(lines[4]["room"], "hall");
    EXPECT_EQ(lines[4]["teleports"], nlohmann::json::array({"annex_west"}));
    EXPECT_EQ(lines[4]["position"], nlohmann::json::array({1, 1.6, 0}));
}

}  // namespace
}  // namespace impossible::app
