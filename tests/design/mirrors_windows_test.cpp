// The designer's tools on a layout with mirrors and windows: only doors are
// walked through (placement, tour, reachability), mirrors and windows are
// counted and drawn apart, and none of them is taken for a door.
#include "design_test_util.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <set>

#include "design/plan.hpp"
#include "design/report.hpp"
#include "design/tour.hpp"
#include "walk/walker.hpp"

namespace design_test {
namespace {

// Rooms a and b share one 4 x 4 m floor, joined by a coincident door in the
// middle. a has a mirror in its -z wall and one in its -x wall, and a window
// in its +x wall whose partner is in b's -x wall. Room c, 2 m north of the
// play area, is seen through a window in b's -z wall and nothing else.
const char* const kPortals =
    "{ \"id\": \"a_b\", \"room\": \"a\", \"center\": [0, 1.05, 0], \"normal\": [0, 0, 1], \"width\": 0.9, "
    "\"height\": 2.1, \"target\": \"b_a\" },\n"
    "{ \"id\": \"b_a\", \"room\": \"b\", \"center\": [0, 1.05, 0], \"normal\": [0, 0, -1], \"width\": 0.9, "
    "\"height\": 2.1, \"target\": \"a_b\" },\n"
    "{ \"id\": \"a_mirror_north\", \"kind\": \"mirror\", \"room\": \"a\", \"center\": [0, 1.5, -2], "
    "\"normal\": [0, 0, 1], \"width\": 1.5, \"height\": 1.5 },\n"
    "{ \"id\": \"a_mirror_west\", \"kind\": \"mirror\", \"room\": \"a\", \"center\": [-2, 1.5, 0], "
    "\"normal\": [1, 0, 0], \"width\": 1, \"height\": 1, \"tint\": [0.7, 0.8, 0.9] },\n"
    "{ \"id\": \"a_window\", \"kind\": \"window\", \"room\": \"a\", \"center\": [2, 1.5, 0], "
    "\"normal\": [-1, 0, 0], \"width\": 1, \"height\": 1, \"target\": \"b_window\" },\n"
    "{ \"id\": \"b_window\", \"kind\": \"window\", \"room\": \"b\", \"center\": [-2, 1.5, 0], "
    "\"normal\": [1, 0, 0], \"width\": 1, \"height\": 1, \"target\": \"a_window\" },\n"
    "{ \"id\": \"b_to_c\", \"kind\": \"window\", \"room\": \"b\", \"center\": [1, 1.5, -2], "
    "\"normal\": [0, 0, 1], \"width\": 1, \"height\": 1, \"reflectance\": 0.3, \"target\": \"c_to_b\" },\n"
    "{ \"id\": \"c_to_b\", \"kind\": \"window\", \"room\": \"c\", \"center\": [1, 1.5, -4], "
    "\"normal\": [0, 0, -1], \"width\": 1, \"height\": 1, \"target\": \"b_to_c\" }";

layout::Layout mirrors_and_windows() {
    return load("{ \"min\": [-3, -3], \"max\": [3, 3] }", "a",
                room("a", -2, -2, 2, 2) + "," + room("b", -2, -2, 2, 2) + "," + room("c", -2, -8, 2, -4), kPortals);
}

int index_of(const layout::Layout& l, const std::string& id) {
    for (std::size_t i = 0; i < l.portals.size(); ++i)
        if (l.portals[i].id == id) return static_cast<int>(i);
    return -1;
}

TEST(DesignMirrors, OnlyDoorsLeadAnywhere) {
    const layout::Layout l = mirrors_and_windows();
    ASSERT_EQ(l.portals.size(), 8u);
    const design::Report r = design::make_report(l);
    EXPECT_TRUE(r.placement.rooms[0].reachable);
    EXPECT_TRUE(r.placement.rooms[1].reachable);
    EXPECT_EQ(r.placement.rooms[1].via, index_of(l, "a_b"));
    EXPECT_EQ(r.placement.rooms[1].doors, 1);
    // c is only seen through a window: no door leads there.
    EXPECT_FALSE(r.placement.rooms[2].reachable);
    EXPECT_EQ(r.unreachable, std::vector<int>{2});
    EXPECT_NE(std::find(r.findings.begin(), r.findings.end(), "no door leads from the start to room \"c\""),
              r.findings.end());
    // c's window lies outside the play area, but is no door to walk through.
    EXPECT_TRUE(r.doors_outside.empty());
    for (const std::string& f : r.findings) EXPECT_EQ(f.find("c_to_b"), std::string::npos) << f;
}

TEST(DesignMirrors, TheReportCountsEachKind) {
    const layout::Layout l = mirrors_and_windows();
    const design::Report r = design::make_report(l);
    EXPECT_EQ(r.summary.portals, 8);
    EXPECT_EQ(r.summary.pairs, 3);
    EXPECT_EQ(r.summary.door_pairs, 1);
    EXPECT_EQ(r.summary.window_pairs, 2);
    EXPECT_EQ(r.summary.mirrors, 2);
    const auto j = design::report_json(l, r, {});
    EXPECT_EQ(j["summary"]["pairs"], 3);
    EXPECT_EQ(j["summary"]["door_pairs"], 1);
    EXPECT_EQ(j["summary"]["window_pairs"], 2);
    EXPECT_EQ(j["summary"]["mirrors"], 2);
    EXPECT_EQ(j["doors_outside_play_area"].size(), 0u);
    const std::string text = design::report_text(l, r);
    EXPECT_NE(text.find("reachable rooms: 2 of 3\n"), std::string::npos) << text;
    EXPECT_NE(text.find("unreachable rooms: c\n"), std::string::npos) << text;
    // A layout of doors only keeps its JSON counts too.
    const layout::Layout doors = load_file("four_rooms.json");
    const auto d = design::report_json(doors, design::make_report(doors), {});
    EXPECT_EQ(d["summary"]["door_pairs"], d["summary"]["pairs"]);
    EXPECT_EQ(d["summary"]["window_pairs"], 0);
    EXPECT_EQ(d["summary"]["mirrors"], 0);
}

TEST(DesignMirrors, TheTourWalksThroughTheDoorOnly) {
    const layout::Layout l = mirrors_and_windows();
    const auto tour = design::plan_tour(l);
    ASSERT_TRUE(tour.has_value()) << tour.error();
    EXPECT_EQ(tour->visited, (std::vector<int>{0, 1}));
    EXPECT_TRUE(tour->missed.empty());  // c is unreachable, not missed
    EXPECT_EQ(tour->teleports, 2);      // into b and back
    walk::Walker walker(l);
    for (const math::HeadPose& pose : tour->poses) {
        for (const int p : walker.step(pose)) EXPECT_EQ(l.portals[p].kind, layout::PortalKind::Door) << l.portals[p].id;
    }
}

TEST(DesignMirrors, ThePlanDrawsMirrorsAndWindowsApart) {
    const layout::Layout l = mirrors_and_windows();
    const design::Drawing d = design::plan_drawing(l, design::make_report(l), {});
    std::set<std::string> doors, mirrors, windows;
    std::vector<std::string> groups;
    for (const design::PlanShape& s : d.shapes) {
        if (groups.empty() || groups.back() != s.group) groups.push_back(s.group);
        if (s.group == "doors") doors.insert(s.name);
        if (s.group == "mirrors") mirrors.insert(s.name);
        if (s.group == "windows") windows.insert(s.name);
    }
    EXPECT_EQ(doors, (std::set<std::string>{"a_b", "b_a"}));
    EXPECT_EQ(mirrors, (std::set<std::string>{"a_mirror_north", "a_mirror_west"}));
    EXPECT_EQ(windows, (std::set<std::string>{"a_window", "b_window", "b_to_c", "c_to_b"}));
    // One run of shapes per group, so the SVG has one <g> each.
    std::set<std::string> seen;
    for (const std::string& g : groups) EXPECT_TRUE(seen.insert(g).second) << g << " appears twice";
    const std::string svg = design::plan_svg(d, 50.0);
    EXPECT_NE(svg.find("<g id=\"mirrors\">"), std::string::npos);
    EXPECT_NE(svg.find("<g id=\"windows\">"), std::string::npos);
    EXPECT_NE(svg.find("data-name=\"a_mirror_west\""), std::string::npos);
    const image::Pixels image = design::plan_raster(d, 20.0);
    EXPECT_GT(image.width, 0);
    // A layout of doors only has no such groups.
    const layout::Layout plain = load_file("default.json");
    for (const design::PlanShape& s : design::plan_drawing(plain, design::make_report(plain), {}).shapes) {
        EXPECT_NE(s.group, "mirrors");
        EXPECT_NE(s.group, "windows");
    }
}

}  // namespace
}  // namespace design_test
