// The designer's commands on layouts with changes (issue 40, item 5), as
// run from the command line: tour's path walked by `walk` visits every room
// and reports the change at the frame the tour's note names; a tour that
// needs a change that can never happen exits 1 naming it and the room;
// validate --json lists the changes; plan draws them dashed.
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "app/run_main_capture.hpp"
#include "common/temp_dir.hpp"

namespace impossible::app::tour_changes_test {
namespace {

using testing::Ran;
using testing::run;

std::string layout_file(const std::string& name) { return std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/" + name; }

std::string read(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// Tours the layout, walks the tour's path, and checks the rooms and the
// frame of the change against the path file's note.
void tour_and_walk(const std::string& name, const std::string& change, const std::set<std::string>& rooms) {
    const test::TempDir dir("tour_changes_" + name);
    const std::string path = (dir.path() / "tour.txt").string();
    const Ran tour = run({"tour", layout_file(name + ".json"), "--out", path});
    ASSERT_EQ(tour.status, 0) << tour.err;
    EXPECT_NE(tour.out.find("changes made: " + change + "\n"), std::string::npos) << tour.out;
    EXPECT_NE(tour.out.find("rooms missed: none\n"), std::string::npos) << tour.out;
    const std::string text = read(path);
    const std::string note = "# change " + change + " is made here, in ";
    const std::size_t at = text.find(note);
    ASSERT_NE(at, std::string::npos) << text.substr(0, 2000);
    const std::size_t frame_at = text.find("(frame ", at);
    const int note_frame = std::stoi(text.substr(frame_at + 7));
    EXPECT_NE(tour.err.find("note: change " + change + " is made here"), std::string::npos) << tour.err;

    const Ran walk = run({"walk", layout_file(name + ".json"), "--path", path});
    ASSERT_EQ(walk.status, 0) << walk.err;
    std::set<std::string> seen;
    int change_frame = -1;
    std::istringstream lines(walk.out);
    for (std::string line; std::getline(lines, line);) {
        const nlohmann::json j = nlohmann::json::parse(line);
        seen.insert(j["room"].get<std::string>());
        if (j.contains("changes")) {
            EXPECT_EQ(j["changes"], nlohmann::json::array({change}));
            EXPECT_EQ(change_frame, -1) << "made twice";
            change_frame = j["frame"].get<int>();
        }
    }
    EXPECT_EQ(seen, rooms);
    EXPECT_EQ(change_frame, note_frame);
}

TEST(TourChanges, DoorSwapTourWalkedByWalkVisitsEveryRoomAndMakesTheSwap) {
    tour_and_walk("door_swap", "swap", {"hall", "study", "garden"});
}

TEST(TourChanges, ReroutedCorridorTourWalkedByWalkVisitsAllFiveRooms) {
    tour_and_walk("rerouted_corridor", "reroute", {"lobby", "blue_corridor", "gallery", "red_corridor", "library"});
}

// door_swap.json with the garden reachable only by the change, which waits
// longer than any tour.
std::string late_swap() {
    std::string text = read(layout_file("door_swap.json"));
    const std::string when = R"("when": { "enter": "study" })";
    text.replace(text.find(when), when.size(), R"("when": { "enter": "study", "time": 5000 })");
    // The study's right door leads back into the hall (hall_right), the
    // garden's door to a door at the garden's far side (garden_back): only
    // the swap leads to the garden.
    const std::string target = R"("target": "garden_door" })";
    text.replace(text.find(target), target.size(), R"("target": "hall_right" })");
    const std::string garden = R"("target": "study_right" })";
    text.replace(text.find(garden), garden.size(), R"("target": "garden_back" })");
    return text;
}

TEST(TourChanges, FailsWithExitOneNamingTheChangeAndTheRoom) {
    const test::TempDir dir("tour_changes_late");
    const std::string file = (dir.path() / "late.json").string();
    std::string text = late_swap();
    const std::string portals = R"("portals": [)";
    text.replace(text.find(portals), portals.size(),
                 R"("portals": [
    { "id": "hall_right", "room": "hall", "center": [1, 1.05, 0], "normal": [0, 0, 1],
      "width": 0.9, "height": 2.1, "target": "study_right" },
    { "id": "garden_back", "room": "garden", "center": [1, 1.05, 2], "normal": [0, 0, -1],
      "width": 0.9, "height": 2.1, "target": "garden_door" },)");
    std::ofstream(file) << text;
    const Ran v = run({"validate", file});
    ASSERT_EQ(v.status, 0) << v.err;
    EXPECT_NE(v.out.find("(1 only after a change: garden after swap)"), std::string::npos) << v.out;
    const std::string out = (dir.path() / "t.txt").string();
    const Ran r = run({"tour", file, "--out", out});
    EXPECT_EQ(r.status, 1) << r.out;
    EXPECT_NE(r.err.find("the tour cannot visit room \"garden\": it needs change \"swap\", which can never happen on "
                         "its route: its time, 5000 s, is more than 300 s after the tour comes to room \"study\""),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(std::ifstream(out).good());
}

TEST(TourChanges, ValidateJsonAndPlanShowTheChanges) {
    const test::TempDir dir("tour_changes_plan");
    const Ran v = run({"validate", layout_file("rerouted_corridor.json"), "--json"});
    ASSERT_EQ(v.status, 0) << v.err;
    const nlohmann::json j = nlohmann::json::parse(v.out);
    ASSERT_EQ(j["changes"].size(), 1u);
    EXPECT_EQ(j["changes"][0]["id"], "reroute");
    EXPECT_EQ(j["changes"][0]["when"]["enter"], "gallery");
    EXPECT_EQ(j["changes"][0]["pairs"], nlohmann::json::parse(R"([["gallery_door", "red_east"]])"));
    const std::string svg = (dir.path() / "plan.svg").string();
    const Ran p = run({"plan", layout_file("rerouted_corridor.json"), "--out", svg});
    ASSERT_EQ(p.status, 0) << p.err;
    const std::string text = read(svg);
    const std::size_t group = text.find("<g id=\"changes\">");
    ASSERT_NE(group, std::string::npos);
    const std::string changes = text.substr(group, text.find("</g>", group) - group);
    EXPECT_NE(changes.find("stroke-dasharray"), std::string::npos) << changes;
    EXPECT_NE(changes.find("data-name=\"reroute: gallery_door/red_east\""), std::string::npos) << changes;
    EXPECT_NE(changes.find(">reroute</text>"), std::string::npos) << changes;
    const std::string png = (dir.path() / "plan.png").string();
    EXPECT_EQ(run({"plan", layout_file("door_swap.json"), "--out", png}).status, 0);
    EXPECT_GT(read(png).size(), 1000u);
}

}  // namespace
}  // namespace impossible::app::tour_changes_test
