// The designer's report on hand-made layouts whose answers are known.
#include <nlohmann/json.hpp>

#include "design_test_util.hpp"

#include "design/report.hpp"

namespace design_test {
namespace {

const std::string kSquare4 = "{ \"min\": [-2, -2], \"max\": [2, 2] }";

TEST(DesignReport, HalfOverlappingSmallRoomsAreUnnoticed) {
    // Two 2 x 4 m rooms sharing a 1 x 4 m strip: 4 of 8 m² = 50 % <= 56 %.
    const auto l =
        load(kSquare4, "a", room("a", -2, -2, 0, 2) + "," + room("b", -1, -2, 1, 2), door_pair("a", "b", -0.5, 0));
    const design::Report r = design::make_report(l);
    ASSERT_EQ(r.overlaps.size(), 1u);
    EXPECT_NEAR(r.overlaps[0].area, 4.0, 1e-9);
    EXPECT_NEAR(r.overlaps[0].percent, 50.0, 1e-9);
    EXPECT_EQ(r.overlaps[0].limit, 56.0);
    EXPECT_FALSE(r.overlaps[0].noticeable);
    EXPECT_TRUE(r.unreachable.empty());
    EXPECT_TRUE(r.findings.empty());
}

TEST(DesignReport, LargeRoomsHaveTheLowerLimit) {
    // Two 5 x 5 m rooms sharing 2 x 5 m: 40 % of 25 m², over the 31 % of larger rooms.
    const auto l = load("{ \"min\": [-5, -5], \"max\": [5, 5] }", "a",
                        room("a", -4, -2.5, 1, 2.5) + "," + room("b", -1, -2.5, 4, 2.5), door_pair("a", "b", 0, 0));
    const design::Report r = design::make_report(l);
    ASSERT_EQ(r.overlaps.size(), 1u);
    EXPECT_NEAR(r.overlaps[0].percent, 40.0, 1e-9);
    EXPECT_EQ(r.overlaps[0].limit, 31.0);
    EXPECT_TRUE(r.overlaps[0].noticeable);
    ASSERT_EQ(r.findings.size(), 1u);
    EXPECT_NE(r.findings[0].find("overlap by 40.0 %"), std::string::npos) << r.findings[0];
}

TEST(DesignReport, ARoomInsideAnotherOverlapsFully) {
    const auto l =
        load(kSquare4, "a", room("a", -2, -2, 2, 2) + "," + room("b", -1, -1, 1, 1.5), door_pair("a", "b", 0, 0));
    const design::Report r = design::make_report(l);
    ASSERT_EQ(r.overlaps.size(), 1u);
    EXPECT_NEAR(r.overlaps[0].percent, 100.0, 1e-9);  // of the smaller room
    EXPECT_TRUE(r.overlaps[0].noticeable);
    EXPECT_NEAR(*r.summary.expansion_ratio, (16.0 + 5.0) / 16.0, 1e-12);
}

TEST(DesignReport, RoomsThatOnlyTouchDoNotOverlap) {
    const auto l = load(kSquare4, "a", room("a", -2, -2, 0, 2) + "," + room("b", 0, -2, 2, 2), "");
    EXPECT_TRUE(design::make_report(l).overlaps.empty());
}

TEST(DesignReport, RoomsNoDoorLeadsToAreUnreachable) {
    // a - b joined; c and d joined to each other only.
    const auto l = load(kSquare4, "a",
                        room("a", -2, -2, 2, 2) + "," + room("b", -2, -2, 2, 2) + "," + room("c", -2, -2, 2, 2) + "," +
                            room("d", -2, -2, 2, 2),
                        door_pair("a", "b", 0, 0) + "," + door_pair("c", "d", 1, 0));
    const design::Report r = design::make_report(l);
    EXPECT_EQ(r.unreachable, (std::vector<int>{2, 3}));
    EXPECT_EQ(r.placement.order, (std::vector<int>{0, 1}));
    EXPECT_EQ(r.overlaps.size(), 6u);  // every pair, all 100 %
    const std::string text = design::report_text(l, r);
    EXPECT_NE(text.find("unreachable rooms: c d\n"), std::string::npos) << text;
    EXPECT_NE(text.find("reachable rooms: 2 of 4\n"), std::string::npos) << text;
}

TEST(DesignReport, RoomsAndDoorsOutsideAnLShapedPlayArea) {
    const std::string l_shape = "{ \"polygon\": [[-2, -2], [2, -2], [2, 0], [0, 0], [0, 2], [-2, 2]] }";
    // b covers the missing north-east quarter by 1 m²; its door stands at (1, 1), outside.
    const auto l =
        load(l_shape, "a", room("a", -2, -2, 0, 2) + "," + room("b", -1, -2, 1, 2) + "," + room("c", -2, -2, 2, 0),
             door_pair("a", "b", -0.5, 0) + "," + door_pair("b", "c", 0.5, -1) + "," +
                 "{ \"id\": \"b_out\", \"room\": \"b\", \"center\": [0.5, 1.05, 1], \"normal\": [0, 0, 1], "
                 "\"width\": 0.9, \"height\": 2.1, \"target\": \"b_out2\" }, "
                 "{ \"id\": \"b_out2\", \"room\": \"b\", \"center\": [-0.5, 1.05, 1.5], \"normal\": [0, 0, 1], "
                 "\"width\": 0.9, \"height\": 2.1, \"target\": \"b_out\" }");
    const design::Report r = design::make_report(l);
    ASSERT_EQ(r.rooms_outside.size(), 1u);
    EXPECT_EQ(r.rooms_outside[0].room, 1);
    EXPECT_NEAR(r.rooms_outside[0].outside_area, 2.0, 1e-9);  // x 0..1, z 0..2
    ASSERT_EQ(r.doors_outside.size(), 1u);
    EXPECT_EQ(l.portals[r.doors_outside[0]].id, "b_out");
    EXPECT_NEAR(*r.summary.play_area_area, 12.0, 1e-12);
    EXPECT_EQ(r.summary.rooms_outside_play_area, std::vector<std::string>{"b"});
}

TEST(DesignReport, TheTunnelLiesBeyondThePlayAreaAsWalked) {
    const auto l = load_file("tunnel.json");
    const design::Report r = design::make_report(l);
    ASSERT_EQ(r.rooms_outside.size(), 1u);
    EXPECT_EQ(l.rooms[r.rooms_outside[0].room].id, "tunnel");
    // Entered through the shed's south door at z = 1: the 10 m tunnel runs from z = 1 to z = -9.
    const math::Polygon2& f = r.floors[r.rooms_outside[0].room];
    double zmin = 1e9, zmax = -1e9;
    for (const auto& p : f) zmin = std::min(zmin, p.y), zmax = std::max(zmax, p.y);
    EXPECT_NEAR(zmax, 1.0, 1e-9);
    EXPECT_NEAR(zmin, -9.0, 1e-9);
}

TEST(DesignReport, JsonHoldsEverySection) {
    const auto l = load_file("four_rooms.json");
    const design::Report r = design::make_report(l);
    const auto j = design::report_json(l, r, {});
    for (const char* key : {"summary", "rooms", "overlaps", "unreachable_rooms", "rooms_outside_play_area",
                            "doors_outside_play_area", "warnings"})
        EXPECT_TRUE(j.contains(key)) << key;
    EXPECT_EQ(j["overlaps"].size(), 6u);
    EXPECT_EQ(j["summary"]["expansion_ratio"], 4.0);
    EXPECT_TRUE(j["unreachable_rooms"].empty());
}

}  // namespace
}  // namespace design_test
