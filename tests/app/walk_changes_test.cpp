// `impossible walk` with changes (layout-format.md, "Changes while walking";
// cli.md, walk): the "changes" key on the frame a change is made, and the
// view options that place the seen test's eyes.
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/cmd_walk.hpp"
#include "layout/layout.hpp"

namespace impossible::app {
namespace {

session::Session door_swap() {
    layout::LoadResult r = layout::load_layout_file(IMPOSSIBLE_SOURCE_DIR "/layouts/door_swap.json");
    EXPECT_TRUE(r.layout);
    return session::Session(std::move(*r.layout));
}

std::vector<nlohmann::json> walked(const session::Session& s, const std::string& path, const WalkSettings& settings,
                                   std::string* err_text = nullptr) {
    std::istringstream in(path);
    std::ostringstream out, err;
    EXPECT_EQ(run_walk_stream(s, in, "walk.txt", out, err, settings), 0) << err.str();
    if (err_text) *err_text = err.str();
    std::vector<nlohmann::json> lines;
    std::istringstream text(out.str());
    for (std::string line; std::getline(text, line);) lines.push_back(nlohmann::json::parse(line));
    return lines;
}

// The frames whose line has "changes", each with its list.
std::vector<std::pair<int, nlohmann::json>> changes_of(const std::vector<nlohmann::json>& lines) {
    std::vector<std::pair<int, nlohmann::json>> out;
    for (const nlohmann::json& l : lines)
        if (l.contains("changes")) out.emplace_back(l["frame"].get<int>(), l["changes"]);
    return out;
}

// Into the study walking backwards, looking at its doors, then turning
// round to the desk by 5° a frame.
std::string backwards_then_turn() {
    std::string path;
    for (int k = 0; k <= 30; ++k) path += "-1 1.6 " + std::to_string(1.5 - 0.1 * k) + " 180 0 0\n";
    for (int k = 1; k <= 36; ++k) path += "-1 1.6 -1.5 " + std::to_string(180 - 5 * k) + " 0 0\n";
    return path;
}

TEST(WalkChanges, TheSwapIsMadeOnTheFrameTheHeadEntersTheStudyLookingAway) {
    const std::vector<nlohmann::json> lines = walked(door_swap(), "-1 1.6 0.05 0 0 0\n-1 1.6 -0.05 0 0 0\n", {});
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_FALSE(lines[0].contains("changes"));
    EXPECT_EQ(lines[1]["room"], "study");
    EXPECT_EQ(lines[1]["changes"], nlohmann::json::array({"swap"}));
    // The key comes last on its line.
    EXPECT_EQ(lines[1].dump().find("\"changes\""), lines[1].dump().rfind("\"changes\""));
}

TEST(WalkChanges, LookingAtTheDoorsHoldsTheChangeBackUntilTheyLeaveTheView) {
    const session::Session s = door_swap();
    std::string err;
    WalkSettings wide;
    const auto made = changes_of(walked(s, backwards_then_turn(), wide, &err));
    ASSERT_EQ(made.size(), 1u);
    // Armed at frame 15 (the study), made only once the turn has taken
    // both eyes' frusta off the four doors.
    EXPECT_GT(made[0].first, 31);
    EXPECT_EQ(err, "");
    WalkSettings narrow;
    narrow.view.fov_y_deg = 20;
    const auto made_narrow = changes_of(walked(s, backwards_then_turn(), narrow));
    ASSERT_EQ(made_narrow.size(), 1u);
    EXPECT_LT(made_narrow[0].first, made[0].first);
    EXPECT_GT(made_narrow[0].first, 15);
}

TEST(WalkChanges, AfterTheSwapTheDoorLeadsIntoTheGardenAndTheOtherIsClosed) {
    std::string path = backwards_then_turn();
    // Turned back round to the doors, then out through the left one (x -1).
    for (int k = 1; k <= 36; ++k) path += "-1 1.6 -1.5 " + std::to_string(5 * k) + " 0 0\n";
    for (int k = 1; k <= 20; ++k) path += "-1 1.6 " + std::to_string(-1.5 + 0.1 * k) + " 180 0 0\n";
    const std::vector<nlohmann::json> lines = walked(door_swap(), path, {});
    const nlohmann::json& last = lines.back();
    EXPECT_EQ(last["room"], "garden");
    // The garden door stands at x 1: the walk came out 2 m east of where
    // the physical head is.
    EXPECT_NEAR(last["position"][0].get<double>(), 1.0, 1e-9);
    int teleports = 0;
    for (const nlohmann::json& l : lines) teleports += static_cast<int>(l["teleports"].size());
    EXPECT_EQ(teleports, 2);  // hall_door, then study_left
}

TEST(WalkChanges, StatsSayHowMuchTheSeenTestCost) {
    WalkSettings settings;
    settings.stats = true;
    std::string err;
    walked(door_swap(), backwards_then_turn(), settings, &err);
    EXPECT_EQ(err.rfind("stats: frames=67 seen_tests=", 0), 0u) << err;
    EXPECT_NE(err.find("seen_us_median="), std::string::npos) << err;
}

}  // namespace
}  // namespace impossible::app
