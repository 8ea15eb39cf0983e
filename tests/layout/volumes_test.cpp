// Volume portals (layout-format.md, "Volume portals"): kind "volume", kept in
// Layout::volumes; a box with required width, height and depth, a target
// room without portals of its own, no overlaps within a room, no hole rule.
#include "layout_test_util.hpp"

namespace layout_test {
namespace {

const std::string kScanner =
    R"({ "id": "scanner", "room": "hall", "kind": "volume", "target": "past", "center": [0, 1.2, 0], )"
    R"("normal": [0, 0, 1], "up": [0, 1, 0], "width": 1.0, "height": 2.4, "depth": 0.6, "tint": [0.8, 0.9, 1.0] })";

// two_rooms.json plus the room "past" (where the hall is, no portals) and
// `volumes` listed before the doors, so that the doors' targets must be
// renumbered.
std::string with_volumes(const std::string& volumes) {
    std::string text = replace_once(two_rooms(), "\"max\": [5, 2.6, 1.5] }",
                                    "\"max\": [5, 2.6, 1.5] },\n    { \"id\": \"past\", \"min\": [-2, 0, -2], "
                                    "\"max\": [2, 3, 2], \"color\": [0.6, 0.5, 0.3] }");
    return replace_once(text, "\"portals\": [", "\"portals\": [\n    " + volumes + ",");
}

std::string scanner_with(const std::string& from, const std::string& to) {
    return with_volumes(replace_once(kScanner, from, to));
}

TEST(LayoutVolumes, AVolumeIsReadIntoVolumes) {
    const Layout l = expect_valid(with_volumes(kScanner));
    ASSERT_EQ(l.volumes.size(), 1u);
    ASSERT_EQ(l.portals.size(), 2u);  // the doors only
    const Volume& v = l.volumes[0];
    EXPECT_EQ(v.id, "scanner");
    EXPECT_EQ(v.room, 0);
    EXPECT_EQ(v.target_room, 2);
    EXPECT_EQ(v.rect.center, glm::dvec3(0, 1.2, 0));
    EXPECT_EQ(v.rect.normal, glm::dvec3(0, 0, 1));
    EXPECT_EQ(v.rect.up, glm::dvec3(0, 1, 0));
    EXPECT_EQ(v.rect.width, 1.0);
    EXPECT_EQ(v.rect.height, 2.4);
    EXPECT_EQ(v.rect.depth, 0.6);
    EXPECT_EQ(v.tint, glm::dvec3(0.8, 0.9, 1.0));
    // The doors' targets index Layout::portals, without the volume.
    EXPECT_EQ(l.portals[0].id, "hall_east");
    EXPECT_EQ(l.portals[0].target, 1);
    EXPECT_EQ(l.portals[1].target, 0);
    EXPECT_EQ(l.portals[0].hole_face, static_cast<int>(Face::PosX));
}

TEST(LayoutVolumes, TintDefaultsToWhiteAndUpIsMadeOrthogonal) {
    const Layout l = expect_valid(with_volumes(replace_once(replace_once(kScanner, ", \"tint\": [0.8, 0.9, 1.0]", ""),
                                                            "\"up\": [0, 1, 0]", "\"up\": [0, 2, 1]")));
    ASSERT_EQ(l.volumes.size(), 1u);
    EXPECT_EQ(l.volumes[0].tint, glm::dvec3(1.0));
    EXPECT_NEAR(l.volumes[0].rect.up.y, 1.0, 1e-12);
    EXPECT_NEAR(l.volumes[0].rect.up.z, 0.0, 1e-12);
}

TEST(LayoutVolumes, WidthHeightAndDepthAreRequired) {
    expect_one_error(scanner_with(", \"depth\": 0.6", ""), "{ \"id\": \"scanner\"",
                     "portals[0]: missing required field \"depth\"");
    expect_one_error(scanner_with("\"width\": 1.0, ", ""), "{ \"id\": \"scanner\"",
                     "portals[0]: missing required field \"width\"");
    expect_one_error(scanner_with("\"depth\": 0.6", "\"depth\": 0"), "0, \"tint\"",
                     "portals[0].depth: must be greater than 0 (got 0)");
    expect_one_error(scanner_with("\"height\": 2.4", "\"height\": -1"), "-1, \"depth\"",
                     "portals[0].height: must be greater than 0 (got -1)");
    // A thin volume is no door box: no warning about eyes behind it.
    const LoadResult thin = load(scanner_with("\"depth\": 0.6", "\"depth\": 0.001"));
    EXPECT_TRUE(thin.layout.has_value()) << all_messages(thin.errors);
    EXPECT_TRUE(thin.warnings.empty()) << all_messages(thin.warnings);
}

TEST(LayoutVolumes, NormalAndUpFollowThePortalRules) {
    expect_one_error(scanner_with("\"normal\": [0, 0, 1]", "\"normal\": [0, 0, 2]"), "[0, 0, 2]",
                     "portals[0].normal: must be a unit vector");
    expect_one_error(scanner_with("\"up\": [0, 1, 0]", "\"up\": [0, 0, -3]"), "[0, 0, -3]",
                     "portals[0].up: must not be parallel to the normal");
}

TEST(LayoutVolumes, ReflectanceIsRefusedTintIsNot) {
    expect_one_error(scanner_with("\"tint\"", "\"reflectance\": 0.2, \"tint\""), "\"reflectance\"",
                     "portals[0].reflectance: a volume has no reflectance");
    expect_one_error(scanner_with("[0.8, 0.9, 1.0]", "[0.8, 1.9, 1.0]"), "1.9",
                     "portals[0].tint[1]: colour component 1.9 is outside 0..1");
}

TEST(LayoutVolumes, TheTargetIsAnExistingRoom) {
    expect_one_error(scanner_with(R"("target": "past", )", ""), "{ \"id\": \"scanner\"",
                     "portals[0]: missing required field \"target\" (the id of the room a volume shows)");
    expect_one_error(scanner_with("\"past\"", "\"future\""), "\"future\"",
                     "portals[0].target: no room has the id \"future\" (a volume's target names a room)");
    expect_one_error(scanner_with("\"past\"", "\"annex_west\""), "\"annex_west\"",
                     "portals[0].target: no room has the id \"annex_west\" (it is a portal's; a volume's target "
                     "names a room)");
    expect_one_error(scanner_with("\"past\"", "7"), "7, \"center\"", "portals[0].target: must be a string");
}

TEST(LayoutVolumes, TheTargetRoomHasNoPortals) {
    expect_one_error(scanner_with("\"past\"", "\"annex\""), "\"annex\", \"center\"",
                     "portals[0].target: the room \"annex\" has portals of its own (\"annex_west\", portals[2]); a "
                     "volume's target room must have none (no doors, mirrors, windows or volumes)");
    // Its own room: the hall has a door besides the volume, which is named.
    expect_one_error(scanner_with("\"past\"", "\"hall\""), "\"hall\", \"center\"",
                     "portals[0].target: the room \"hall\" has portals of its own (\"hall_east\", portals[1])");
    // A volume alone in its room, showing that room.
    expect_one_error(scanner_with("\"room\": \"hall\"", "\"room\": \"past\""), "\"past\", \"center\"",
                     "portals[0].target: a volume cannot show its own room \"past\"");
    // Another volume in the target room is a portal too.
    const std::string other =
        R"({ "id": "back", "room": "past", "kind": "volume", "target": "annex", "center": [0, 1, 0], )"
        R"("normal": [0, 0, 1], "width": 1, "height": 1, "depth": 1 })";
    const LoadResult r = load(with_volumes(kScanner + ",\n    " + other));
    EXPECT_TRUE(has_error(r, position_of(with_volumes(kScanner + ",\n    " + other), "\"past\", \"center\""),
                          "portals[0].target: the room \"past\" has portals of its own (\"back\", portals[1])"))
        << all_messages(r.errors);
    EXPECT_TRUE(has_error(r, position_of(with_volumes(kScanner + ",\n    " + other), "\"annex\", \"center\""),
                          "portals[1].target: the room \"annex\" has portals of its own"))
        << all_messages(r.errors);
}

TEST(LayoutVolumes, IdsAreUniqueAmongAllPortals) {
    // (hall_east's target is then the volume, the first with that id: an error too.)
    expect_error(scanner_with("\"scanner\"", "\"annex_west\""), "\"annex_west\"",
                 "portals[2].id: duplicate portal id \"annex_west\" (also used by portals[0])", 2);
    // A door cannot target a volume.
    const std::string text =
        replace_once(with_volumes(kScanner), "\"target\": \"annex_west\"", "\"target\": \"scanner\"");
    const LoadResult r = load(text);
    EXPECT_TRUE(has_error(r, position_of(text, "\"scanner\" }"),
                          "portals[1].target: \"scanner\" is a volume, which has no partner (its target is a room); "
                          "a door must target a door that names it back"))
        << all_messages(r.errors);
}

TEST(LayoutVolumes, AnUnknownRoomIsReported) {
    expect_one_error(scanner_with("\"room\": \"hall\"", "\"room\": \"attic\""), "\"attic\"",
                     "portals[0].room: no room has the id \"attic\"");
}

// A second volume in the hall, centred on `center`, turned by `normal`.
std::string second_volume(const std::string& center, const std::string& normal, const std::string& room = "hall") {
    return R"({ "id": "second", "room": ")" + room + R"(", "kind": "volume", "target": "past", "center": )" + center +
           R"(, "normal": )" + normal + R"(, "width": 1, "height": 1, "depth": 1 })";
}

TEST(LayoutVolumes, VolumesOfARoomDoNotOverlap) {
    // The scanner spans x -0.5..0.5, y 0..2.4, z -0.3..0.3.
    const std::string overlapping = with_volumes(kScanner + ",\n    " + second_volume("[0.9, 1, 0]", "[0, 0, 1]"));
    expect_one_error(overlapping, "[0.9, 1, 0]",
                     "portals[1].center: the volume overlaps the volume \"scanner\" (portals[0]) in the room \"hall\" "
                     "(the volumes of a room must not overlap; touching is allowed)");
    // Touching along x is allowed, as is a volume of another room in the same place.
    expect_valid(with_volumes(kScanner + ",\n    " + second_volume("[1, 1, 0]", "[0, 0, 1]")));
    const LoadResult other_room =
        load(with_volumes(kScanner + ",\n    " + second_volume("[3, 1, 0]", "[0, 0, 1]", "annex")));
    // (The annex has a door, so "second" is fine but the rule on targets is not broken: it targets "past".)
    EXPECT_TRUE(other_room.layout.has_value()) << all_messages(other_room.errors);
}

TEST(LayoutVolumes, OverlapIsTestedOnTheTurnedBoxes) {
    // A 1 m cube at the origin's height and one turned 45° about y, beside
    // its corner: their bounding boxes overlap, the boxes do not.
    const std::string cube =
        R"({ "id": "cube", "room": "hall", "kind": "volume", "target": "past", "center": [0, 1, 0], )"
        R"("normal": [0, 0, 1], "width": 1, "height": 1, "depth": 1 })";
    const std::string turned = "[0.70710678118654752, 0, 0.70710678118654752]";
    expect_valid(with_volumes(cube + ",\n    " + second_volume("[1.2, 1, 1.2]", turned)));
    expect_one_error(with_volumes(cube + ",\n    " + second_volume("[0.8, 1, 0.8]", turned)), "[0.8, 1, 0.8]",
                     "portals[1].center: the volume overlaps the volume \"cube\"");
    // Turned about the edge axes too: a cube tilted 45° about x, just clear of the other's top.
    const std::string tilted = "[0, 0.70710678118654752, 0.70710678118654752]";
    expect_valid(with_volumes(cube + ",\n    " + second_volume("[0, 2.21, 0]", tilted)));
    expect_one_error(with_volumes(cube + ",\n    " + second_volume("[0, 2.1, 0]", tilted)), "[0, 2.1, 0]",
                     "portals[1].center: the volume overlaps");
}

TEST(LayoutVolumes, TheHoleRuleDoesNotApply) {
    // In the plane of the hall's -z wall and partly beyond it: a door there
    // would be an error ("partly inside the face"); a volume is not.
    const Layout l = expect_valid(
        scanner_with("\"center\": [0, 1.2, 0], \"normal\": [0, 0, 1], \"up\": [0, 1, 0], \"width\": 1.0",
                     "\"center\": [0, 1.2, -2], \"normal\": [0, 0, 1], \"up\": [0, 1, 0], \"width\": 6.0"));
    ASSERT_EQ(l.volumes.size(), 1u);
    const LoadResult r = load(scanner_with("[0, 1.2, 0]", "[1.8, 1.2, 0]"));  // partly outside the hall: fine
    EXPECT_TRUE(r.layout.has_value()) << all_messages(r.errors);
    EXPECT_TRUE(r.warnings.empty()) << all_messages(r.warnings);
}

TEST(LayoutVolumes, AVolumeWhollyOutsideItsRoomIsAWarning) {
    const std::string text = scanner_with("[0, 1.2, 0]", "[10, 1.2, 0]");
    const LoadResult r = load(text);
    ASSERT_TRUE(r.layout.has_value()) << all_messages(r.errors);
    ASSERT_EQ(r.warnings.size(), 1u) << all_messages(r.warnings);
    const Pos want = position_of(text, "[10, 1.2, 0]");
    EXPECT_EQ(r.warnings[0].line, want.line);
    EXPECT_EQ(r.warnings[0].column, want.column);
    EXPECT_EQ(r.warnings[0].message,
              "portals[0].center: the volume lies wholly outside its room \"hall\", so nothing in the room is seen "
              "through it");
    // Touching the room's wall from outside is outside too.
    EXPECT_EQ(load(scanner_with("[0, 1.2, 0]", "[2.5, 1.2, 0]")).warnings.size(), 1u);
}

TEST(LayoutVolumes, TheSummaryCountsVolumesOnlyWhenThereAreSome) {
    const Layout with = expect_valid(with_volumes(kScanner));
    const std::string text = summary_text(with, summarize(with));
    EXPECT_NE(text.find("\nvolumes: 1\n"), std::string::npos) << text;
    EXPECT_EQ(summarize(with).portals, 2);
    const Layout without = expect_valid(two_rooms());
    EXPECT_EQ(summary_text(without, summarize(without)).find("volumes"), std::string::npos);
}

}  // namespace
}  // namespace layout_test
