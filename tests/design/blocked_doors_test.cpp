// Doors a prop blocks (issue 38): a table standing in a doorway, a moving
// crate parked in front of a door. validate names them and the rooms behind
// them; tour misses those rooms and says why; a looping crate, which comes
// back, blocks nothing.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "design/report.hpp"
#include "design/tour.hpp"

namespace {

using namespace impossible;

// Three rooms in a row along x (hall, annex, store), joined by doors in
// their walls; `table` and `crate_motion` say what stands where.
std::string row_of_rooms(bool table, const std::string& crate_motion) {
    const std::string table_prop =
        table ? R"("props": [ { "id": "table", "box": { "min": [3.4, 0, 1.6], "max": [4.0, 0.8, 2.4] } } ])"
              : R"("props": [])";
    const std::string crate = crate_motion.empty() ? "" : R"(, "motion": )" + crate_motion;
    return R"({ "format": "impossible-layout", "version": 1,
  "play_area": { "min": [-1, -1], "max": [13, 5] },
  "start": { "room": "hall", "position": [1, 1.6, 2] },
  "rooms": [
    { "id": "hall", "min": [0, 0, 0], "max": [4, 3, 4], )" +
           table_prop + R"( },
    { "id": "annex", "min": [4, 0, 0], "max": [8, 3, 4],
      "props": [ { "box": { "min": [4.5, 0, 0.2], "max": [4.9, 2, 0.6] } },
                 { "id": "crate", "box": { "min": [5.5, 0, 1.6], "max": [6.1, 0.6, 2.4] })" +
           crate + R"( } ] },
    { "id": "store", "min": [8, 0, 0], "max": [12, 3, 4] }
  ],
  "portals": [
    { "id": "hall_east", "room": "hall", "center": [4, 1.05, 2], "normal": [-1, 0, 0], "width": 0.9, "height": 2.1, "target": "annex_west" },
    { "id": "annex_west", "room": "annex", "center": [4, 1.05, 2], "normal": [1, 0, 0], "width": 0.9, "height": 2.1, "target": "hall_east" },
    { "id": "annex_east", "room": "annex", "center": [8, 1.05, 2], "normal": [-1, 0, 0], "width": 0.9, "height": 2.1, "target": "store_west" },
    { "id": "store_west", "room": "store", "center": [8, 1.05, 2], "normal": [1, 0, 0], "width": 0.9, "height": 2.1, "target": "annex_east" }
  ]
})";
}

layout::Layout load(const std::string& text) {
    layout::LoadResult r = layout::load_layout_text(text, "row.json", ".");
    std::string errors;
    for (const auto& d : r.errors) errors += d.str() + "\n";
    EXPECT_TRUE(r.layout.has_value()) << errors;
    return r.layout.value_or(layout::Layout{});
}

const char* const kParked = R"({ "path": [[0, 0, 0, 0], [2, 1.5, 0, 0]] })";
const char* const kLooping = R"({ "path": [[0, 0, 0, 0], [2, 1.5, 0, 0], [4, 0, 0, 0]], "loop": true })";

TEST(BlockedDoors, ATableInADoorwayIsAFindingNamingTheDoorAndTheProp) {
    const layout::Layout l = load(row_of_rooms(true, ""));
    const design::Report r = design::make_report(l);
    ASSERT_EQ(r.blocked.size(), 1u);
    EXPECT_EQ(l.portals[r.blocked[0].portal].id, "hall_east");
    EXPECT_EQ(design::obstacle_name(l, r.blocked[0].by), "rooms[0].props[0] (table)");
    ASSERT_EQ(r.findings.size(), 1u);
    EXPECT_EQ(r.findings[0],
              "door \"hall_east\" is blocked by rooms[0].props[0] (table): nobody walks through it, so no tour "
              "reaches rooms \"annex\", \"store\"");
    const std::string text = design::report_text(l, r);
    EXPECT_NE(text.find("reachable rooms: 3 of 3\nunreachable rooms: none\n"
                        "  door \"hall_east\" is blocked by rooms[0].props[0] (table)\n"
                        "rooms behind blocked doors: annex store\n"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("findings: 1\n"), std::string::npos) << text;
    const auto j = design::report_json(l, r, {});
    ASSERT_EQ(j["blocked_doors"].size(), 1u);
    EXPECT_EQ(j["blocked_doors"][0]["door"], "hall_east");
    EXPECT_EQ(j["blocked_doors"][0]["blocked_by"]["room"], "hall");
    EXPECT_EQ(j["blocked_doors"][0]["blocked_by"]["index"], 0);
    EXPECT_EQ(j["blocked_doors"][0]["blocked_by"]["id"], "table");
    EXPECT_EQ(j["blocked_doors"][0]["rooms_behind"], nlohmann::ordered_json({"annex", "store"}));
}

TEST(BlockedDoors, TheTourSaysWhyItMissedTheRoomsBehind) {
    const layout::Layout l = load(row_of_rooms(true, ""));
    const auto tour = design::plan_tour(l);
    ASSERT_TRUE(tour.has_value());
    ASSERT_EQ(tour->missed.size(), 2u);
    ASSERT_EQ(tour->why.size(), 2u);
    EXPECT_EQ(l.rooms[tour->missed[0]].id, "annex");
    EXPECT_EQ(tour->why[0], "door \"hall_east\" is blocked by rooms[0].props[0] (table)");
    EXPECT_EQ(tour->why[1],
              "it lies beyond room \"annex\": door \"hall_east\" is blocked by rooms[0].props[0] (table)");
}

TEST(BlockedDoors, AMovingCrateParkedInFrontOfADoorBlocksItWhereItRests) {
    const layout::Layout l = load(row_of_rooms(false, kParked));
    const design::Report r = design::make_report(l);
    ASSERT_EQ(r.blocked.size(), 1u);
    EXPECT_EQ(l.portals[r.blocked[0].portal].id, "annex_east");
    EXPECT_EQ(design::obstacle_name(l, r.blocked[0].by), "rooms[1].props[1] (crate) where its motion leaves it");
    ASSERT_EQ(r.behind_blocked[0].size(), 1u);
    EXPECT_EQ(l.rooms[r.behind_blocked[0][0]].id, "store");
    const auto tour = design::plan_tour(l);
    ASSERT_TRUE(tour.has_value());
    ASSERT_EQ(tour->missed.size(), 1u);
    EXPECT_EQ(l.rooms[tour->missed[0]].id, "store");
    EXPECT_EQ(tour->why[0], "door \"annex_east\" is blocked by rooms[1].props[1] (crate) where its motion leaves it");
}

TEST(BlockedDoors, NothingBlockedTheTourVisitsEveryRoomAsBefore) {
    for (const std::string& motion : {std::string(), std::string(kLooping)}) {
        const layout::Layout l = load(row_of_rooms(false, motion));
        const design::Report r = design::make_report(l);
        EXPECT_TRUE(r.blocked.empty()) << motion;
        EXPECT_TRUE(r.findings.empty()) << motion;
        EXPECT_EQ(design::report_text(l, r).find("blocked"), std::string::npos);
        const auto tour = design::plan_tour(l);
        ASSERT_TRUE(tour.has_value());
        EXPECT_EQ(tour->visited.size(), 3u) << motion;
        EXPECT_TRUE(tour->missed.empty());
        EXPECT_TRUE(tour->why.empty());
    }
}

}  // namespace
