// Rooms: ids, boxes, colours, face colours, checker, box props.
#include "layout_test_util.hpp"

namespace layout_test {
namespace {

TEST(LayoutRooms, IdsMustMatchThePatternAndBeUnique) {
    expect_error(replace_once(two_rooms(), "\"id\": \"annex\"", "\"id\": \"an nex\""), "\"an nex\"",
                 "rooms[1].id: id \"an nex\" must be letters, digits, '_' and '-' only");
    const std::string empty = replace_once(two_rooms(), "\"id\": \"annex\"", "\"id\": \"\"");
    const LoadResult r = load(empty);
    EXPECT_TRUE(has_error(r, position_of(empty, "\"\", \"min\""), "rooms[1].id: id \"\" must be"))
        << all_messages(r.errors);
    const std::string dup = replace_once(two_rooms(), "\"id\": \"annex\"", "\"id\": \"hall\"");
    const LoadResult d = load(dup);
    EXPECT_TRUE(has_error(d, position_of(dup, "\"hall\"", 2),
                          "rooms[1].id: duplicate room id \"hall\" (also used by rooms[0])"))
        << all_messages(d.errors);
    expect_error(replace_once(two_rooms(), "\"id\": \"annex\"", "\"id\": 5"), "5, \"min\"",
                 "rooms[1].id: must be a string (got a number)");
    const Layout layout = expect_valid(replace_all(two_rooms(), "\"annex\"", "\"Annex_2-b\""));
    EXPECT_EQ(layout.rooms[1].id, "Annex_2-b");
}

TEST(LayoutRooms, MissingRequiredFieldsAreReportedAtTheRoom) {
    const std::string text = replace_once(two_rooms(), "\"min\": [2, 0, -1.5], ", "");
    expect_one_error(text, "{ \"id\": \"annex\"", "rooms[1]: missing required field \"min\"");
}

TEST(LayoutRooms, MaxMustExceedMinOnEveryAxis) {
    expect_one_error(replace_once(two_rooms(), "\"max\": [5, 2.6, 1.5]", "\"max\": [5, 0, 1.5]"), "[5, 0, 1.5]",
                     "rooms[1].max: must be greater than min on every axis (y: 0 <= 0)");
    expect_one_error(replace_once(two_rooms(), "\"max\": [5, 2.6, 1.5]", "\"max\": [1, 2.6, 1.5]"), "[1, 2.6, 1.5]",
                     "rooms[1].max: must be greater than min on every axis (x: 1 <= 2)");
    expect_one_error(replace_once(two_rooms(), "\"max\": [5, 2.6, 1.5]", "\"max\": [5, 2.6, -1.4999999999]"),
                     "[5, 2.6, -1.4999999999]", "rooms[1].max: the room is too thin (z: ");
}

TEST(LayoutRooms, CoordinatesMustBeNumbersOfSaneSize) {
    expect_one_error(replace_once(two_rooms(), "\"min\": [2, 0, -1.5]", "\"min\": [2, \"0\", -1.5]"), "\"0\"",
                     "rooms[1].min[1]: must be a number (got a string)");
    expect_one_error(replace_once(two_rooms(), "\"min\": [2, 0, -1.5]", "\"min\": [2, 0, -1e308]"), "-1e308",
                     "rooms[1].min[2]: -1e+308 is out of range (|value| must be at most 100000 m)");
    expect_one_error(replace_once(two_rooms(), "\"min\": [2, 0, -1.5]", "\"min\": [2, 0, null]"), "null",
                     "rooms[1].min[2]: must be a number (got null)");
    expect_one_error(replace_once(two_rooms(), "\"min\": [2, 0, -1.5]", "\"min\": {}"), "{}",
                     "rooms[1].min: must be an array of 3 numbers [x, y, z] (got an object)");
    // -0 and integers written with exponents are ordinary numbers.
    const Layout layout = expect_valid(replace_once(two_rooms(), "\"min\": [-2, 0, -2]", "\"min\": [-2e0, -0, -2]"));
    EXPECT_EQ(layout.rooms[0].min, glm::dvec3(-2, 0, -2));
}

TEST(LayoutRooms, ColoursAreThreeComponentsInZeroToOne) {
    expect_one_error(replace_once(two_rooms(), "[0.80, 0.78, 0.72]", "[0.80, 1.5, 0.72]"), "1.5, 0.72",
                     "rooms[0].color[1]: colour component 1.5 is outside 0..1");
    expect_one_error(replace_once(two_rooms(), "[0.80, 0.78, 0.72]", "[0.80, 0.78, -0.1]"), "-0.1",
                     "rooms[0].color[2]: colour component -0.1 is outside 0..1");
    expect_one_error(replace_once(two_rooms(), "[0.80, 0.78, 0.72]", "[0.80, 0.78, 0.72, 1]"), "[0.80, 0.78, 0.72, 1]",
                     "rooms[0].color: must be an array of 3 numbers [r, g, b] (got an array of 4)");
    const Layout layout = expect_valid(replace_once(two_rooms(), "[0.80, 0.78, 0.72]", "[0, 1, 0.5]"));
    EXPECT_EQ(layout.rooms[0].face_color[int(Face::Ceiling)], glm::dvec3(0, 1, 0.5));
}

TEST(LayoutRooms, FaceColorsNameTheSixFaces) {
    const std::string all_faces =
        "{ \"floor\": [0.1, 0, 0], \"ceiling\": [0.2, 0, 0], \"-x\": [0.3, 0, 0], \"+x\": [0.4, 0, 0], "
        "\"-z\": [0.5, 0, 0], \"+z\": [0.6, 0, 0] }";
    const Layout layout = expect_valid(replace_once(two_rooms(), "{ \"floor\": [0.3, 0.3, 0.35] }", all_faces));
    for (int f = 0; f < kFaceCount; ++f) {
        EXPECT_DOUBLE_EQ(layout.rooms[0].face_color[static_cast<std::size_t>(f)].r, 0.1 * (f + 1)) << f;
    }
    expect_one_error(replace_once(two_rooms(), "\"floor\": [0.3", "\"wall\": [0.3"), "\"wall\"",
                     "rooms[0].face_colors.wall: unknown face \"wall\"");
    expect_one_error(replace_once(two_rooms(), "\"floor\": [0.3, 0.3, 0.35]", "\"+x\": [0.3, 0.3, 2.5]"), "2.5]",
                     "rooms[0].face_colors.+x[2]: colour component 2.5 is outside 0..1");
    expect_one_error(replace_once(two_rooms(), "{ \"floor\": [0.3, 0.3, 0.35] }", "[]"), "[]",
                     "rooms[0].face_colors: must be an object (got an array)");
}

TEST(LayoutRooms, CheckerMustBePositive) {
    expect_one_error(replace_once(two_rooms(), "\"checker\": 0.5", "\"checker\": 0e0"), "0e0",
                     "rooms[0].checker: must be greater than 0 (got 0)");
    expect_one_error(replace_once(two_rooms(), "\"checker\": 0.5", "\"checker\": -1"), "-1",
                     "rooms[0].checker: must be greater than 0 (got -1)");
    expect_one_error(replace_once(two_rooms(), "\"checker\": 0.5", "\"checker\": 1e-9"), "1e-9",
                     "rooms[0].checker: 1e-09 is too small (the minimum is 1e-06 m)");
    expect_one_error(replace_once(two_rooms(), "\"checker\": 0.5", "\"checker\": true"), "true",
                     "rooms[0].checker: must be a number (got a boolean)");
}

TEST(LayoutRooms, BoxPropsNeedMinBelowMaxAndTakeTheRoomColour) {
    const std::string no_colour = replace_once(two_rooms(), ", \"color\": [0.9, 0.2, 0.2]", "");
    const Layout layout = expect_valid(no_colour);
    const auto& box = std::get<BoxProp>(layout.rooms[0].props[0]);
    EXPECT_EQ(box.min, glm::dvec3(-0.3, 0, -0.3));
    EXPECT_EQ(box.max, glm::dvec3(0.3, 0.9, 0.3));
    EXPECT_EQ(box.color, glm::dvec3(0.80, 0.78, 0.72));  // the room's colour, not the floor's

    expect_one_error(replace_once(two_rooms(), "\"max\": [0.3, 0.9, 0.3]", "\"max\": [0.3, -0.9, 0.3]"),
                     "[0.3, -0.9, 0.3]",
                     "rooms[0].props[0].box.max: must be greater than min on every axis (y: -0.9 <= 0)");
    expect_one_error(replace_once(two_rooms(), ", \"max\": [0.3, 0.9, 0.3]", ""), "{ \"min\": [-0.3",
                     "rooms[0].props[0].box: missing required field \"max\"");
    expect_one_error(replace_once(two_rooms(), "[0.9, 0.2, 0.2]", "[0.9, 0.2]"), "[0.9, 0.2]",
                     "rooms[0].props[0].color: must be an array of 3 numbers [r, g, b]");
    expect_one_error(replace_once(two_rooms(), "\"color\": [0.9, 0.2, 0.2]", "\"size\": 2"), "\"size\"",
                     "rooms[0].props[0].size: unknown field \"size\"");
}

TEST(LayoutRooms, APropIsABoxOrAModel) {
    const std::string both = replace_once(two_rooms(), "\"color\": [0.9, 0.2, 0.2]", "\"gltf\": \"x.glb\"");
    expect_one_error(both, "{ \"box\"", "rooms[0].props[0]: a prop is either a \"box\" or a \"gltf\" model, not both");
    const std::string neither =
        replace_once(two_rooms(), "{ \"box\": { \"min\": [-0.3, 0, -0.3], \"max\": [0.3, 0.9, 0.3] }, ", "{ ");
    expect_one_error(neither, "{ \"color\"", "rooms[0].props[0]: a prop needs a \"box\" or a \"gltf\" field");
    expect_one_error(replace_once(two_rooms(), "\"props\": [", "\"props\": [ 33, "), "33, ",
                     "rooms[0].props[0]: must be an object (got a number)");
    expect_one_error(replace_once(two_rooms(), "\"max\": [5, 2.6, 1.5] }", "\"max\": [5, 2.6, 1.5], \"props\": {} }"),
                     "{} }", "rooms[1].props: must be an array (got an object)");
}

}  // namespace
}  // namespace layout_test
