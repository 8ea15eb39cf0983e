// Portals: room and target links, vectors, sizes, pairs.
#include <glm/geometric.hpp>

#include "layout_test_util.hpp"

namespace layout_test {
namespace {

const char* const kEastPortal =
    "{ \"id\": \"hall_east\", \"room\": \"hall\",\n"
    "      \"center\": [2.0, 1.1, 0.0], \"normal\": [-1, 0, 0], \"up\": [0, 1, 0],\n"
    "      \"width\": 1.0, \"height\": 2.2, \"depth\": 0.25,\n"
    "      \"target\": \"annex_west\" }";

TEST(LayoutPortals, TheTestTextMatchesTheFile) { EXPECT_NE(two_rooms().find(kEastPortal), std::string::npos); }

TEST(LayoutPortals, RoomMustExist) {
    expect_one_error(replace_once(two_rooms(), "\"room\": \"annex\"", "\"room\": \"attic\""), "\"attic\"",
                     "portals[1].room: no room has the id \"attic\"");
    expect_one_error(replace_once(two_rooms(), "\"room\": \"annex\"", "\"room\": 17"), "17,",
                     "portals[1].room: must be a string (got a number)");
}

TEST(LayoutPortals, TargetMustExistAndNameThePortalBack) {
    expect_error(replace_once(two_rooms(), "\"target\": \"annex_west\"", "\"target\": \"nowhere\""), "\"nowhere\"",
                 "portals[0].target: no portal has the id \"nowhere\"");
    // Three portals in a cycle: hall_east → annex_west → third → hall_east.
    std::string text = replace_once(two_rooms(), "\"target\": \"hall_east\"", "\"target\": \"third\"");
    text = replace_once(text, "\n  ]\n}",
                        ",\n    { \"id\": \"third\", \"room\": \"annex\", \"center\": [4, 1, 0], "
                        "\"normal\": [-1, 0, 0], \"width\": 1, \"height\": 2.2, "
                        "\"target\": \"hall_east\" }\n  ]\n}");
    const LoadResult r = load(text);
    EXPECT_TRUE(has_error(r, position_of(text, "\"annex_west\""),
                          "portals[0].target: portal \"annex_west\" targets \"third\", not \"hall_east\" "
                          "(paired portals must name each other)"))
        << all_messages(r.errors);
    EXPECT_TRUE(has_error(r, position_of(text, "\"third\""),
                          "portals[1].target: portal \"third\" targets \"hall_east\", not \"annex_west\""))
        << all_messages(r.errors);
    EXPECT_TRUE(has_error(r, position_of(text, "\"hall_east\" }"),
                          "portals[2].target: portal \"hall_east\" targets \"annex_west\", not \"third\""))
        << all_messages(r.errors);
    EXPECT_EQ(r.errors.size(), 3u) << all_messages(r.errors);
}

TEST(LayoutPortals, APortalCannotTargetItself) {
    std::string text = replace_once(two_rooms(), "\"target\": \"annex_west\"", "\"target\": \"hall_east\"");
    const LoadResult r = load(text);
    EXPECT_TRUE(has_error(r, position_of(text, "\"hall_east\" }"), "portals[0].target: a portal cannot target itself"))
        << all_messages(r.errors);
}

TEST(LayoutPortals, RequiredFieldsAreReportedAtThePortal) {
    const std::string text =
        replace_once(two_rooms(), "\"center\": [2.0, 1.1, 0.0], \"normal\": [-1, 0, 0], ", "\"normal\": [-1, 0, 0], ");
    expect_one_error(text, "{ \"id\": \"hall_east\"", "portals[0]: missing required field \"center\"");
    const std::string no_target = replace_once(two_rooms(), ",\n      \"target\": \"annex_west\"", "");
    const LoadResult r = load(no_target);
    EXPECT_TRUE(has_error(r, position_of(no_target, "{ \"id\": \"hall_east\""),
                          "portals[0]: missing required field \"target\""))
        << all_messages(r.errors);
}

TEST(LayoutPortals, NormalMustBeUnitWithinATolerance) {
    expect_one_error(replace_once(two_rooms(), "\"normal\": [-1, 0, 0]", "\"normal\": [-2, 0, 0]"), "[-2, 0, 0]",
                     "portals[0].normal: must be a unit vector (its length is 2; allowed is 1 ± 0.001)");
    expect_one_error(replace_once(two_rooms(), "\"normal\": [-1, 0, 0]", "\"normal\": [0, 0, 0]"), "[0, 0, 0]",
                     "portals[0].normal: must not be the zero vector");
    const Layout layout =
        expect_valid(replace_once(two_rooms(), "\"normal\": [-1, 0, 0]", "\"normal\": [-1.0009, 0, 0]"));
    EXPECT_EQ(layout.portals[0].rect.normal, glm::dvec3(-1, 0, 0));  // normalised
    const Layout tilted =
        expect_valid(replace_once(two_rooms(), "\"normal\": [1, 0, 0]", "\"normal\": [0.8, 0.0005, 0.6]"));
    EXPECT_NEAR(glm::length(tilted.portals[1].rect.normal), 1.0, 1e-15);
}

TEST(LayoutPortals, UpMustNotBeParallelToTheNormalAndIsOrthogonalised) {
    expect_one_error(replace_once(two_rooms(), "\"up\": [0, 1, 0]", "\"up\": [-1, 0.01, 0]"), "[-1, 0.01, 0]",
                     "portals[0].up: must not be parallel to the normal (the angle between them is 0.57");
    expect_one_error(replace_once(two_rooms(), "\"up\": [0, 1, 0]", "\"up\": [1, 0, 0]"), "[1, 0, 0]",
                     "portals[0].up: must not be parallel to the normal (the angle between them is 0°");
    expect_one_error(replace_once(two_rooms(), "\"up\": [0, 1, 0]", "\"up\": [0, 0, 0]"), "[0, 0, 0]",
                     "portals[0].up: must not be the zero vector");
    // 2° away from the normal is allowed; up is made orthogonal and unit.
    const double a = 2.0 * 3.14159265358979323846 / 180.0;
    const std::string up = "[" + std::to_string(-std::cos(a)) + ", " + std::to_string(std::sin(a)) + ", 0]";
    const Layout layout = expect_valid(replace_once(two_rooms(), "\"up\": [0, 1, 0]", "\"up\": " + up));
    EXPECT_NEAR(layout.portals[0].rect.up.x, 0.0, 1e-12);
    EXPECT_NEAR(layout.portals[0].rect.up.y, 1.0, 1e-12);
    const Layout slanted = expect_valid(replace_once(two_rooms(), "\"up\": [0, 1, 0]", "\"up\": [0.5, 2, 0]"));
    EXPECT_EQ(slanted.portals[0].rect.up, glm::dvec3(0, 1, 0));
}

TEST(LayoutPortals, AFloorPortalNeedsAnUp) {
    const std::string text = replace_once(two_rooms(), "\"normal\": [1, 0, 0]", "\"normal\": [0, 1, 0]");
    expect_error(text, "[0, 1, 0],\n      \"width\": 1.0, \"height\": 2.2,\n      \"target\": \"hall_east\"",
                 "portals[1].normal: is parallel to the default up [0, 1, 0]");
}

TEST(LayoutPortals, SizesMustBePositive) {
    expect_error(replace_once(two_rooms(), "\"width\": 1.0, \"height\": 2.2, \"depth\"",
                              "\"width\": 0, \"height\": 2.2, \"depth\""),
                 "0, \"height\"", "portals[0].width: must be greater than 0 (got 0)");
    expect_error(replace_once(two_rooms(), "\"height\": 2.2, \"depth\"", "\"height\": -2.2, \"depth\""), "-2.2",
                 "portals[0].height: must be greater than 0 (got -2.2)");
    expect_one_error(replace_once(two_rooms(), "\"depth\": 0.25", "\"depth\": 0"), "0,\n      \"target\"",
                     "portals[0].depth: must be greater than 0 (got 0)");
    const Layout layout = expect_valid(replace_once(two_rooms(), "\"depth\": 0.25", "\"depth\": 0.5"));
    EXPECT_EQ(layout.portals[0].rect.depth, 0.5);
}

TEST(LayoutPortals, PairedPortalsMustHaveTheSameSize) {
    const std::string text =
        replace_all(two_rooms(), "\"width\": 1.0, \"height\": 2.2,\n      \"target\": \"hall_east\"",
                    "\"width\": 1.1, \"height\": 2.3,\n      \"target\": \"hall_east\"");
    const LoadResult r = load(text);
    EXPECT_TRUE(has_error(r, position_of(text, "1.1, \"height\""),
                          "portals[1].width: 1.1 differs from the width 1 of its target \"hall_east\""))
        << all_messages(r.errors);
    EXPECT_TRUE(has_error(r, position_of(text, "2.3,"),
                          "portals[1].height: 2.3 differs from the height 2.2 of its target \"hall_east\""))
        << all_messages(r.errors);
    // Within 1e-6 they count as equal.
    expect_valid(replace_once(two_rooms(), "\"width\": 1.0, \"height\": 2.2,\n      \"target\": \"hall_east\"",
                              "\"width\": 1.0000005, \"height\": 2.2,\n      \"target\": \"hall_east\""));
}

TEST(LayoutPortals, IdsAreUniqueAndPortalsAnArray) {
    std::string text = replace_once(two_rooms(), "\"id\": \"annex_west\"", "\"id\": \"hall_east\"");
    const LoadResult r = load(text);
    EXPECT_TRUE(has_error(r, position_of(text, "\"hall_east\"", 1),
                          "portals[1].id: duplicate portal id \"hall_east\" (also used by portals[0])"))
        << all_messages(r.errors);
    const std::string no_portals = two_rooms().substr(0, two_rooms().find(",\n  \"portals\"")) + "\n}\n";
    const Layout layout = expect_valid(no_portals);
    EXPECT_TRUE(layout.portals.empty());
    const std::string object = no_portals.substr(0, no_portals.rfind('}')) + ", \"portals\": {}}";
    expect_one_error(object, "{}}", "portals: must be an array (got an object)");
}

TEST(LayoutPortals, CoincidentPortalsInOverlappingRoomsStandFree) {
    const LoadResult r = load_layout_file(kLayoutDir + "/impossible.json");
    ASSERT_TRUE(r.layout.has_value()) << all_messages(r.errors);
    EXPECT_EQ(r.layout->portals[0].hole_face, -1);
    EXPECT_EQ(r.layout->portals[1].hole_face, -1);
    EXPECT_EQ(r.layout->portals[0].target, 1);
    EXPECT_EQ(r.layout->portals[1].target, 0);
}

TEST(LayoutPortals, AShallowBoxIsAWarningWithTheDepthToUse) {
    // Half an IPD behind the plane an eye must still be inside the box.
    const std::string text = replace_once(two_rooms(), "\"depth\": 0.25", "\"depth\": 0.02");
    const LoadResult r = load(text);
    EXPECT_TRUE(r.layout.has_value()) << all_messages(r.errors);
    ASSERT_EQ(r.warnings.size(), 1u);
    const Pos want = position_of(text, "0.02,");
    EXPECT_EQ(r.warnings[0].line, want.line);
    EXPECT_EQ(r.warnings[0].column, want.column);
    EXPECT_EQ(r.warnings[0].message,
              "portals[0].depth: the box is 0.02 m deep: an eye half an IPD (0.032 m) behind the door's plane sees "
              "out of its back; make it at least 0.033 m");
    // Deep enough for the default depth mode, not for 24-bit standard depth.
    const LoadResult s = load(replace_once(two_rooms(), "\"depth\": 0.25", "\"depth\": 0.04"));
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].message.find("with --depth standard (near plane 0.01 m)"), std::string::npos)
        << s.warnings[0].message;
    EXPECT_NE(s.warnings[0].message.find("at least 0.042 m"), std::string::npos);
    EXPECT_TRUE(load(two_rooms()).warnings.empty());
}

}  // namespace
}  // namespace layout_test
