// What the designer's commands say about a layout a walker cannot get
// through (issue 38): validate lists the blocked door and the prop, tour
// says on standard error why it missed a room (exit 0, as for any room it
// misses), and a door whose normal points out of its room is one warning
// line from validate, trace, plan and tour alike.
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "app/commands.hpp"
#include "app/run_main_capture.hpp"
#include "common/temp_dir.hpp"

namespace impossible::app {
namespace {

using testing::Ran;
using testing::run;

// Two rooms side by side joined by doors in their shared wall at x = 4;
// `table` puts a table in front of the hall's door; `normal` is the hall
// door's.
std::string two_rooms(bool table, const std::string& normal = "[-1, 0, 0]") {
    const std::string props =
        table ? R"(, "props": [ { "id": "table", "box": { "min": [3.4, 0, 1.6], "max": [4.0, 0.8, 2.4] } } ])" : "";
    return R"({ "format": "impossible-layout", "version": 1,
  "play_area": { "min": [-1, -1], "max": [9, 5] },
  "start": { "room": "hall", "position": [1, 1.6, 2] },
  "rooms": [ { "id": "hall", "min": [0, 0, 0], "max": [4, 3, 4])" +
           props + R"( },
             { "id": "annex", "min": [4, 0, 0], "max": [8, 3, 4] } ],
  "portals": [
    { "id": "east", "room": "hall", "center": [4, 1.05, 2], "normal": )" +
           normal + R"(, "width": 0.9, "height": 2.1, "target": "west" },
    { "id": "west", "room": "annex", "center": [4, 1.05, 2], "normal": [1, 0, 0], "width": 0.9, "height": 2.1, "target": "east" }
  ]
})";
}

std::string write(const test::TempDir& dir, const std::string& name, const std::string& text) {
    const std::string path = (dir.path() / name).string();
    std::ofstream(path) << text;
    return path;
}

TEST(DesignerFindings, ValidateNamesTheBlockedDoorAndItsProp) {
    const test::TempDir dir("designer_findings_validate");
    const std::string file = write(dir, "blocked.json", two_rooms(true));
    const Ran text = run({"validate", file});
    EXPECT_EQ(text.status, 0) << text.err;
    EXPECT_NE(text.out.find("  door \"east\" is blocked by rooms[0].props[0] (table)\n"
                            "rooms behind blocked doors: annex\n"),
              std::string::npos)
        << text.out;
    EXPECT_NE(text.out.find("findings: 1\n"), std::string::npos) << text.out;
    EXPECT_NE(text.err.find(": door \"east\" is blocked by rooms[0].props[0] (table): nobody walks through it, so no "
                            "tour reaches room \"annex\"\n"),
              std::string::npos)
        << text.err;
    const Ran json = run({"validate", file, "--json"});
    EXPECT_EQ(json.status, 0);
    EXPECT_NE(json.out.find("\"blocked_doors\": [\n    {\n      \"door\": \"east\""), std::string::npos) << json.out;
}

TEST(DesignerFindings, TourSaysWhyItMissedARoomAndExitsZero) {
    const test::TempDir dir("designer_findings_tour");
    const std::string blocked = write(dir, "blocked.json", two_rooms(true));
    const Ran r = run({"tour", blocked, "--out", (dir.path() / "t.txt").string()});
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("rooms missed: annex\n"), std::string::npos) << r.out;
    EXPECT_EQ(r.err,
              "warning: the tour could not reach room \"annex\": door \"east\" is blocked by rooms[0].props[0] "
              "(table)\n");
    // Nothing in the way: the tour's output is as it was, nothing on standard error.
    const std::string clear = write(dir, "clear.json", two_rooms(false));
    const Ran ok = run({"tour", clear, "--out", (dir.path() / "u.txt").string()});
    EXPECT_EQ(ok.status, 0) << ok.err;
    EXPECT_NE(ok.out.find("rooms missed: none\n"), std::string::npos) << ok.out;
    EXPECT_EQ(ok.err, "");
}

TEST(DesignerFindings, ADoorFacingOutOfItsRoomIsOneWarningLineInEveryCommand) {
    const test::TempDir dir("designer_findings_normal");
    const std::string file = write(dir, "out.json", two_rooms(false, "[1, 0, 0]"));
    const std::string warning = "warning: " + file +
                                ":7:71: portals[0].normal: door \"east\" lies in the +x face of room \"hall\" but its "
                                "normal points out of the room, so it makes no hole: it stands free, hidden in the "
                                "face, and nobody can see or walk through it; flip the normal to [-1, 0, 0]\n";
    const Ran validate = run({"validate", file});
    EXPECT_EQ(validate.status, 0);
    EXPECT_EQ(validate.err.find(warning), 0u) << validate.err;
    const Ran trace = run({"trace", file, "--size", "32x18", "--out", (dir.path() / "t.png").string()});
    EXPECT_EQ(trace.status, 0) << trace.err;
    EXPECT_NE(trace.err.find(warning), std::string::npos) << trace.err;
    const Ran plan = run({"plan", file, "--out", (dir.path() / "p.svg").string()});
    EXPECT_EQ(plan.err.find(warning), 0u) << plan.err;
    const Ran tour = run({"tour", file, "--out", (dir.path() / "t.txt").string()});
    EXPECT_EQ(tour.err.find(warning), 0u) << tour.err;
}

}  // namespace
}  // namespace impossible::app
