// Prop ids and motions (layout-format.md, "Moving props, hands and crossing
// objects"): ids unique among all props, a moving prop needs one, and the
// motion path's keys, times and loop.
#include "layout_test_util.hpp"

namespace layout_test {
namespace {

const std::string kHallProp = "\"color\": [0.9, 0.2, 0.2] }";

// two_rooms.json with `fields` added to the hall's box prop.
std::string hall_prop_with(const std::string& fields) {
    return replace_once(two_rooms(), kHallProp, "\"color\": [0.9, 0.2, 0.2], " + fields + " }");
}

// two_rooms.json with the annex holding `props` (a JSON array's entries).
std::string annex_props(const std::string& text, const std::string& props) {
    return replace_once(text, "\"max\": [5, 2.6, 1.5] }", "\"max\": [5, 2.6, 1.5], \"props\": [" + props + "] }");
}

std::string moving(const std::string& motion) { return hall_prop_with("\"id\": \"crate\", \"motion\": " + motion); }

TEST(LayoutMovingProps, IdsAndMotionsAreRead) {
    const std::string text = annex_props(
        moving(R"({"path": [[0, 0, 0, 0], [2, 1.5, 0, -0.5], [3.5, 0, 0.25, 0]], "loop": true})"),
        R"({"gltf": ")" + kChairGlb + R"(", "position": [3, 0, 0], "id": "chair-2", "motion": {"path": [[0, 0, 0, 1]]}},
           {"box": {"min": [3, 0, 0], "max": [3.5, 0.5, 0.5]}, "id": "still_box"})");
    const Layout l = expect_valid(text);
    ASSERT_EQ(l.rooms.size(), 2u);
    ASSERT_EQ(l.rooms[0].props.size(), 1u);
    const Prop& crate = l.rooms[0].props[0];
    EXPECT_EQ(prop_id(crate), "crate");
    const Motion& m = prop_motion(crate);
    ASSERT_EQ(m.keys.size(), 3u);
    EXPECT_TRUE(m.loop);
    EXPECT_EQ(m.keys[0].t, 0.0);
    EXPECT_EQ(m.keys[1].t, 2.0);
    EXPECT_EQ(m.keys[1].offset, glm::dvec3(1.5, 0, -0.5));
    EXPECT_EQ(m.keys[2].t, 3.5);
    EXPECT_EQ(m.keys[2].offset, glm::dvec3(0, 0.25, 0));
    // The box itself is as before.
    EXPECT_EQ(std::get<BoxProp>(crate).min, glm::dvec3(-0.3, 0, -0.3));
    EXPECT_EQ(std::get<BoxProp>(crate).color, glm::dvec3(0.9, 0.2, 0.2));

    ASSERT_EQ(l.rooms[1].props.size(), 2u);
    const auto& chair = std::get<GltfProp>(l.rooms[1].props[0]);
    EXPECT_EQ(chair.id, "chair-2");
    ASSERT_EQ(chair.motion.keys.size(), 1u);  // one key: a constant offset
    EXPECT_EQ(chair.motion.keys[0].offset, glm::dvec3(0, 0, 1));
    EXPECT_FALSE(chair.motion.loop);  // the default
    EXPECT_FALSE(chair.triangles.empty());
    EXPECT_EQ(prop_id(l.rooms[1].props[1]), "still_box");  // an id without a motion
    EXPECT_TRUE(prop_motion(l.rooms[1].props[1]).keys.empty());
}

TEST(LayoutMovingProps, PropsWithoutIdOrMotionLoadAsBefore) {
    const Layout l = expect_valid(two_rooms());
    ASSERT_EQ(l.rooms[0].props.size(), 1u);
    EXPECT_EQ(prop_id(l.rooms[0].props[0]), "");
    EXPECT_TRUE(prop_motion(l.rooms[0].props[0]).keys.empty());
}

TEST(LayoutMovingProps, AnIdHasTheRoomIdCharacters) {
    const std::string text = hall_prop_with("\"id\": \"red crate\"");
    expect_one_error(text, "\"red crate\"",
                     "rooms[0].props[0].id: id \"red crate\" must be letters, digits, '_' and '-' only");
    expect_one_error(hall_prop_with("\"id\": \"\""), "\"\" }", "rooms[0].props[0].id: id \"\" must be letters");
    expect_one_error(hall_prop_with("\"id\": 7"), "7 }", "rooms[0].props[0].id: must be a string (got a number)");
}

TEST(LayoutMovingProps, PropIdsAreUniqueInTheWholeLayout) {
    // In another room.
    const std::string text = annex_props(hall_prop_with("\"id\": \"crate\""),
                                         R"({"box": {"min": [3, 0, 0], "max": [4, 1, 1]}, "id": "crate"})");
    expect_one_error(text, "\"crate\"",
                     "rooms[1].props[0].id: duplicate prop id \"crate\" (also used by rooms[0].props[0]; prop ids "
                     "are unique in the whole layout)",
                     1);
    // In the same room, a box and a model.
    const std::string same =
        replace_once(hall_prop_with("\"id\": \"crate\""), "}\n      ] }",
                     "},\n        {\"gltf\": \"" + kChairGlb + "\", \"id\": \"crate\"}\n      ] }");
    expect_one_error(same, "\"crate\"",
                     "rooms[0].props[1].id: duplicate prop id \"crate\" (also used by rooms[0].props[0]", 1);
    // Ids of props need not differ from room or portal ids.
    expect_valid(hall_prop_with("\"id\": \"hall\""));
    expect_valid(hall_prop_with("\"id\": \"hall_east\""));
}

TEST(LayoutMovingProps, AMovingPropNeedsAnId) {
    const std::string text = hall_prop_with("\"motion\": {\"path\": [[0, 0, 0, 0], [1, 1, 0, 0]]}");
    expect_one_error(text, "{ \"box\"",
                     "rooms[0].props[0]: missing field \"id\": a prop with a \"motion\" needs an id");
    const std::string gltf =
        annex_props(two_rooms(), "{\"gltf\": \"" + kChairGlb +
                                     "\", \"position\": [3, 0, 0], \"motion\": {\"path\": [[0, 0, 0, 0]]}}");
    expect_one_error(gltf, "{\"gltf\"", "rooms[1].props[0]: missing field \"id\"");
}

TEST(LayoutMovingProps, TheFirstKeyIsAtTimeZero) {
    const std::string text = moving(R"({"path": [[0.5, 0, 0, 0], [1, 1, 0, 0]]})");
    expect_one_error(text, "0.5, 0, 0, 0",
                     "rooms[0].props[0].motion.path[0][0]: the first key's time must be 0 (got 0.5)");
    // A negative time is out of range where it is written.
    expect_one_error(moving(R"({"path": [[-1, 0, 0, 0]]})"), "-1, 0, 0, 0",
                     "rooms[0].props[0].motion.path[0][0]: must not be negative (got -1)");
}

TEST(LayoutMovingProps, TimesIncreaseStrictly) {
    expect_one_error(moving(R"({"path": [[0, 0, 0, 0], [2, 1, 0, 0], [2, 2, 0, 0]]})"), "2, 2",
                     "rooms[0].props[0].motion.path[2][0]: must be greater than the time 2 of the key before it "
                     "(times increase strictly)");
    expect_one_error(moving(R"({"path": [[0, 0, 0, 0], [2, 1, 0, 0], [1, 2, 0, 0]]})"), "1, 2",
                     "rooms[0].props[0].motion.path[2][0]: must be greater than the time 2");
    // A key that cannot be read does not cause a second error at the next.
    expect_one_error(moving(R"({"path": [[0, 0, 0, 0], [1, "x", 0, 0], [2, 2, 0, 0]]})"), "\"x\"",
                     "rooms[0].props[0].motion.path[1][1]: must be a number (got a string)");
}

TEST(LayoutMovingProps, KeysAreFourFiniteNumbersInRange) {
    expect_one_error(moving(R"({"path": [[0, 0, 0]]})"), "[0, 0, 0]]}",
                     "rooms[0].props[0].motion.path[0]: must be an array of 4 numbers [t, dx, dy, dz] (got an array "
                     "of 3)");
    expect_one_error(moving(R"({"path": [5]})"), "5]}",
                     "rooms[0].props[0].motion.path[0]: must be an array of 4 numbers [t, dx, dy, dz] (got a number)");
    expect_one_error(moving(R"({"path": [[0, 0, 0, 0], [1, 0, 200000, 0]]})"), "200000",
                     "rooms[0].props[0].motion.path[1][2]: 200000 is out of range (|value| must be at most 100000 m)");
    expect_one_error(moving(R"({"path": [[0, 0, 0, 0], [2e6, 0, 0, 0]]})"), "2e6",
                     "rooms[0].props[0].motion.path[1][0]: 2000000 is too large (the maximum is 1000000 s)");
    expect_valid(moving(R"({"path": [[0, 0, 0, 0], [1, 0, 0, -1e5], [1e6, 0, 0, 0]]})"));  // the limits are allowed
}

TEST(LayoutMovingProps, APathHasAtLeastOneKeyAndAtMostTheLimit) {
    expect_one_error(moving(R"({"path": []})"), "[]",
                     "rooms[0].props[0].motion.path: a motion needs at least one key [t, dx, dy, dz]");
    expect_one_error(moving(R"({"loop": true})"), "{\"loop\"",
                     "rooms[0].props[0].motion: missing required field \"path\"");
    expect_one_error(moving(R"({"path": {"t": 0}})"), "{\"t\"",
                     "rooms[0].props[0].motion.path: must be an array (got an object)");
    std::string keys = "[0, 0, 0, 0]";
    for (int i = 1; i <= 10000; ++i) keys += ", [" + std::to_string(i) + ", 0, 0, 0]";
    expect_one_error(moving("{\"path\": [" + keys + "]}"), "[[0, 0",
                     "rooms[0].props[0].motion.path: has 10001 entries; at most 10000 are allowed");
}

TEST(LayoutMovingProps, LoopIsABooleanAndNeedsTwoKeys) {
    expect_one_error(moving(R"({"path": [[0, 0, 0, 0], [1, 1, 0, 0]], "loop": 1})"), "1}",
                     "rooms[0].props[0].motion.loop: must be true or false (got a number)");
    expect_one_error(moving(R"({"path": [[0, 0, 0, 0]], "loop": true})"), "true",
                     "rooms[0].props[0].motion.loop: a looping motion needs at least two keys");
    // One key that holds still is fine without a loop, and "loop": false is the default.
    const Layout l = expect_valid(moving(R"({"path": [[0, 0, 0, 0]], "loop": false})"));
    EXPECT_FALSE(prop_motion(l.rooms[0].props[0]).loop);
}

TEST(LayoutMovingProps, AMotionIsAnObjectWithKnownFields) {
    expect_one_error(moving(R"({"path": [[0, 0, 0, 0]], "lop": true})"), "\"lop\"",
                     "rooms[0].props[0].motion.lop: unknown field \"lop\" (did you mean \"loop\"?)");
    expect_one_error(moving(R"([[0, 0, 0, 0]])"), "[[0, 0, 0, 0]]",
                     "rooms[0].props[0].motion: must be an object (got an array)");
    // Comments are allowed in it, as everywhere.
    expect_valid(moving(R"({"_note": "slides", "path": [[0, 0, 0, 0]]})"));
}

TEST(LayoutMovingProps, EveryProblemIsReported) {
    // A bad id, a bad key and a bad loop in one prop, and a moving prop
    // without an id in the annex: four errors, in file order.
    const std::string text =
        annex_props(hall_prop_with(R"("id": "a b", "motion": {"path": [[1, 0, 0, 0]], "loop": "yes"})"),
                    R"({"box": {"min": [3, 0, 0], "max": [4, 1, 1]}, "motion": {"path": [[0, 0, 0, 0]]}})");
    const LoadResult r = load(text);
    EXPECT_FALSE(r.layout.has_value());
    ASSERT_EQ(r.errors.size(), 4u) << all_messages(r.errors);
    EXPECT_NE(r.errors[0].message.find(".id: id \"a b\""), std::string::npos) << all_messages(r.errors);
    EXPECT_NE(r.errors[1].message.find("path[0][0]: the first key's time"), std::string::npos);
    EXPECT_NE(r.errors[2].message.find("motion.loop: must be true or false"), std::string::npos);
    EXPECT_NE(r.errors[3].message.find("rooms[1].props[0]: missing field \"id\""), std::string::npos);
}

}  // namespace
}  // namespace layout_test
