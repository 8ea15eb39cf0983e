// The top level of a layout: format, version, name, play_area, start,
// unknown fields and comments, and a whole valid file read back.
#include "layout_test_util.hpp"

namespace layout_test {
namespace {

TEST(LayoutTopLevel, ReadsTheValidTwoRoomLayout) {
    const Layout layout = expect_valid(two_rooms());
    EXPECT_EQ(layout.source, "t.json");
    EXPECT_EQ(layout.name, "Two rooms, one doorway");
    ASSERT_TRUE(layout.play_area.has_value());
    EXPECT_EQ(layout.play_area->min, glm::dvec2(-2, -2));
    EXPECT_EQ(layout.play_area->max, glm::dvec2(2, 2));
    EXPECT_EQ(layout.start.room, 0);
    EXPECT_EQ(layout.start.position, glm::dvec3(0, 1.6, 1));
    EXPECT_EQ(layout.start.yaw_deg, 0.0);
    ASSERT_EQ(layout.rooms.size(), 2u);
    const Room& hall = layout.rooms[0];
    EXPECT_EQ(hall.id, "hall");
    EXPECT_EQ(hall.min, glm::dvec3(-2, 0, -2));
    EXPECT_EQ(hall.max, glm::dvec3(2, 3, 2));
    EXPECT_EQ(hall.face_color[int(Face::Floor)], glm::dvec3(0.3, 0.3, 0.35));
    EXPECT_EQ(hall.face_color[int(Face::Ceiling)], glm::dvec3(0.80, 0.78, 0.72));
    EXPECT_EQ(hall.face_color[int(Face::PosZ)], glm::dvec3(0.80, 0.78, 0.72));
    EXPECT_EQ(hall.checker, 0.5);
    ASSERT_EQ(hall.props.size(), 1u);
    ASSERT_TRUE(std::holds_alternative<BoxProp>(hall.props[0]));
    EXPECT_EQ(std::get<BoxProp>(hall.props[0]).color, glm::dvec3(0.9, 0.2, 0.2));
    const Room& annex = layout.rooms[1];
    EXPECT_EQ(annex.face_color[int(Face::NegX)], glm::dvec3(0.8));  // the default colour
    EXPECT_EQ(annex.checker, 0.0);
    ASSERT_EQ(layout.portals.size(), 2u);
    const Portal& east = layout.portals[0];
    EXPECT_EQ(east.id, "hall_east");
    EXPECT_EQ(east.room, 0);
    EXPECT_EQ(east.target, 1);
    EXPECT_EQ(east.rect.center, glm::dvec3(2, 1.1, 0));
    EXPECT_EQ(east.rect.normal, glm::dvec3(-1, 0, 0));
    EXPECT_EQ(east.rect.up, glm::dvec3(0, 1, 0));
    EXPECT_EQ(east.rect.width, 1.0);
    EXPECT_EQ(east.rect.height, 2.2);
    EXPECT_EQ(east.hole_face, int(Face::PosX));
    const Portal& west = layout.portals[1];
    EXPECT_EQ(west.room, 1);
    EXPECT_EQ(west.target, 0);
    EXPECT_EQ(west.rect.depth, 0.25);  // the default
    EXPECT_EQ(west.hole_face, int(Face::NegX));
}

TEST(LayoutTopLevel, ReadsAFileAndNamesItInDiagnostics) {
    const LoadResult good = load_layout_file(kLayoutDir + "/two_rooms.json");
    EXPECT_TRUE(good.layout.has_value()) << all_messages(good.errors);
    EXPECT_EQ(good.layout->source, kLayoutDir + "/two_rooms.json");

    const std::string bad_path = kLayoutDir + "/bad_room_max.json";
    const LoadResult bad = load_layout_file(bad_path);
    ASSERT_EQ(bad.errors.size(), 1u) << all_messages(bad.errors);
    EXPECT_EQ(bad.errors[0].str(),
              bad_path + ":10:14: rooms[1].max: must be greater than min on every axis (y: 0 <= 0)");
}

TEST(LayoutTopLevel, FormatMustBeImpossibleLayout) {
    expect_one_error(replace_once(two_rooms(), "\"impossible-layout\"", "\"impossible\""), "\"impossible\"",
                     "format: must be \"impossible-layout\" (got \"impossible\")");
    expect_one_error(replace_once(two_rooms(), "\"impossible-layout\"", "7"), "7,",
                     "format: must be a string (got a number)");
}

TEST(LayoutTopLevel, RequiredTopLevelFieldsAreReportedAtTheObject) {
    const std::string text = replace_once(two_rooms(), "\"format\": \"impossible-layout\",", "");
    expect_one_error(text, "{", "missing required field \"format\"");
    expect_one_error(replace_once(two_rooms(), "\"version\": 1,", ""), "{", "missing required field \"version\"");
}

TEST(LayoutTopLevel, VersionMustBeOne) {
    expect_one_error(replace_once(two_rooms(), "\"version\": 1", "\"version\": 2"), "2,",
                     "version: unsupported version 2 (this program reads version 1)");
    expect_one_error(replace_once(two_rooms(), "\"version\": 1", "\"version\": \"1\""), "\"1\"",
                     "version: must be the number 1 (got a string)");
    expect_valid(replace_once(two_rooms(), "\"version\": 1", "\"version\": 1.0"));
}

TEST(LayoutTopLevel, NameIsOptionalButMustBeAString) {
    const Layout layout = expect_valid(replace_once(two_rooms(), "\"name\": \"Two rooms, one doorway\",", ""));
    EXPECT_EQ(layout.name, "");
    expect_one_error(replace_once(two_rooms(), "\"Two rooms, one doorway\"", "[1]"), "[1]",
                     "name: must be a string (got an array)");
}

TEST(LayoutTopLevel, UnknownFieldsAreErrorsAtTheirKey) {
    const std::string text = replace_once(two_rooms(), "\"name\":", "\"nmae\":");
    expect_one_error(text, "\"nmae\"", "nmae: unknown field \"nmae\" (did you mean \"name\"?)");
    const std::string room = replace_once(two_rooms(), "\"checker\": 0.5", "\"checkers\": 0.5");
    expect_one_error(room, "\"checkers\"", "rooms[0].checkers: unknown field \"checkers\"");
    const std::string odd = replace_once(two_rooms(), "\"name\":", "\"a b\": 1, \"name\":");
    expect_one_error(odd, "\"a b\"", "[\"a b\"]: unknown field \"a b\"");
}

TEST(LayoutTopLevel, FieldsStartingWithUnderscoreAreComments) {
    std::string text = replace_once(two_rooms(), "\"id\": \"hall\",", "\"id\": \"hall\", \"_note\": {\"x\": [1]},");
    text = replace_once(text, "\"floor\":", "\"_old\": 5, \"floor\":");
    text = replace_once(text, "\"id\": \"hall_east\",", "\"id\": \"hall_east\", \"_\": null,");
    text = replace_once(text, "\"yaw_deg\": 0.0", "\"yaw_deg\": 0.0, \"_why\": \"facing north\"");
    expect_valid(text);
}

TEST(LayoutTopLevel, TheTopLevelMustBeAnObject) {
    expect_one_error("[1, 2]", "[", "a layout must be a JSON object (got an array)");
    expect_one_error("\"layout\"", "\"", "a layout must be a JSON object (got a string)");
}

TEST(LayoutTopLevel, StartNeedsAnExistingRoomAndAPosition) {
    expect_one_error(replace_once(two_rooms(), "\"room\": \"hall\", \"position\"", "\"room\": \"attic\", \"position\""),
                     "\"attic\"", "start.room: no room has the id \"attic\"");
    const std::string no_position = replace_once(two_rooms(), "\"position\": [0.0, 1.6, 1.0], ", "");
    expect_one_error(no_position, "{ \"room\": \"hall\"", "start: missing required field \"position\"");
    expect_one_error(replace_once(two_rooms(), "[0.0, 1.6, 1.0]", "[0.0, 1.6]"), "[0.0, 1.6]",
                     "start.position: must be an array of 3 numbers [x, y, z] (got an array of 2)");
    expect_one_error(replace_once(two_rooms(), "\"yaw_deg\": 0.0", "\"yaw_deg\": \"north\""), "\"north\"",
                     "start.yaw_deg: must be a number (got a string)");
    expect_one_error(replace_once(two_rooms(), "\"yaw_deg\": 0.0", "\"yaw_deg\": 1e300"), "1e300",
                     "start.yaw_deg: 1e+300 is out of range");
    const std::string no_start = replace_once(
        two_rooms(), "\"start\": { \"room\": \"hall\", \"position\": [0.0, 1.6, 1.0], \"yaw_deg\": 0.0 },", "");
    expect_one_error(no_start, "{", "missing required field \"start\"");
}

TEST(LayoutTopLevel, StartYawDefaultsToZeroAndIsKept) {
    const Layout a = expect_valid(replace_once(two_rooms(), ", \"yaw_deg\": 0.0", ""));
    EXPECT_EQ(a.start.yaw_deg, 0.0);
    const Layout b = expect_valid(replace_once(two_rooms(), "\"yaw_deg\": 0.0", "\"yaw_deg\": -90"));
    EXPECT_EQ(b.start.yaw_deg, -90.0);
}

TEST(LayoutTopLevel, StartingOutsideTheRoomIsAWarningOnly) {
    const std::string text = replace_once(two_rooms(), "[0.0, 1.6, 1.0]", "[3.0, 1.6, 1.0]");
    const LoadResult r = load(text);
    EXPECT_TRUE(r.layout.has_value()) << all_messages(r.errors);
    ASSERT_EQ(r.warnings.size(), 1u);
    const Pos want = position_of(text, "[3.0, 1.6, 1.0]");
    EXPECT_EQ(r.warnings[0].line, want.line);
    EXPECT_EQ(r.warnings[0].column, want.column);
    EXPECT_EQ(r.warnings[0].message, "start.position: the head starts outside its room \"hall\"");
    EXPECT_TRUE(load(two_rooms()).warnings.empty());
}

TEST(LayoutTopLevel, PlayAreaIsOptionalWithMinBelowMax) {
    const Layout none =
        expect_valid(replace_once(two_rooms(), "\"play_area\": { \"min\": [-2.0, -2.0], \"max\": [2.0, 2.0] },", ""));
    EXPECT_FALSE(none.play_area.has_value());
    expect_one_error(replace_once(two_rooms(), "\"max\": [2.0, 2.0]", "\"max\": [2.0, -2.0]"), "[2.0, -2.0]",
                     "play_area.max: must be greater than min on both axes (z: -2 <= -2)");
    expect_one_error(replace_once(two_rooms(), "\"max\": [2.0, 2.0]", "\"max\": [-1.9999999, 2.0]"),
                     "[-1.9999999, 2.0]", "play_area.max: the play area is too small (x: ");
    expect_one_error(replace_once(two_rooms(), "\"min\": [-2.0, -2.0]", "\"min\": [-2.0, 0, -2.0]"), "[-2.0, 0, -2.0]",
                     "play_area.min: must be an array of 2 numbers [x, z] (got an array of 3)");
    expect_one_error(replace_once(two_rooms(), "\"min\": [-2.0, -2.0], ", ""), "{ \"max\"",
                     "play_area: missing required field \"min\"");
    expect_one_error(replace_once(two_rooms(), "{ \"min\": [-2.0, -2.0], \"max\": [2.0, 2.0] }", "true"), "true",
                     "play_area: must be an object (got a boolean)");
}

TEST(LayoutTopLevel, RoomsMustBeANonEmptyArray) {
    const std::string text = two_rooms();
    const std::size_t begin = text.find("\"rooms\": [");
    const std::size_t end = text.find("\"portals\"");
    const std::string empty_rooms = text.substr(0, begin) + "\"rooms\": [],\n  " + text.substr(end);
    const LoadResult r = load(empty_rooms);
    const Pos at = position_of(empty_rooms, "[],");
    EXPECT_TRUE(has_error(r, at, "rooms: must hold at least one room")) << all_messages(r.errors);
    const std::string object_rooms = text.substr(0, begin) + "\"rooms\": {},\n  " + text.substr(end);
    EXPECT_TRUE(
        has_error(load(object_rooms), position_of(object_rooms, "{},"), "rooms: must be an array (got an object)"));
}

TEST(LayoutTopLevel, DiagnosticStrFormats) {
    EXPECT_EQ((Diagnostic{"a.json", 12, 17, "rooms[1].max: bad"}).str(), "a.json:12:17: rooms[1].max: bad");
    EXPECT_EQ((Diagnostic{"a.json", 0, 0, "the file does not exist"}).str(), "a.json: the file does not exist");
}

TEST(LayoutTopLevel, FindRoom) {
    const Layout layout = expect_valid(two_rooms());
    EXPECT_EQ(find_room(layout, "hall"), 0);
    EXPECT_EQ(find_room(layout, "annex"), 1);
    EXPECT_EQ(find_room(layout, "attic"), -1);
}

}  // namespace
}  // namespace layout_test
