// Changes while walking (layout-format.md, "Changes while walking"): the
// top-level `changes` array, its errors (each at the field, with its line and
// column) and its warnings (a change that can never happen, one that changes
// nothing).
#include "layout_test_util.hpp"

namespace layout_test {
namespace {

// A hall with a study east of it and a garden west of it, a mirror, a
// volume (listed first, so that the doors' indices in Layout::portals are
// one less than in the file) showing the room "past", a smaller pair of
// doors between the study and the garden, and an attic whose two doors lead
// to each other: no door reaches it from the hall.
//
// Rooms: hall 0, study 1, garden 2, past 3, attic 4. Layout::portals:
// hall_east 0, study_west 1, hall_mirror 2, hall_west 3, garden_east 4,
// study_south 5, garden_south 6, attic_a 7, attic_b 8.
const std::string kLayout = R"({
  "format": "impossible-layout",
  "version": 1,
  "start": { "room": "hall", "position": [0.0, 1.6, 1.0] },
  "rooms": [
    { "id": "hall", "min": [-2, 0, -2], "max": [2, 3, 2] },
    { "id": "study", "min": [2, 0, -1.5], "max": [5, 2.6, 1.5] },
    { "id": "garden", "min": [-5, 0, -1.5], "max": [-2, 2.6, 1.5] },
    { "id": "past", "min": [-2, 0, -2], "max": [2, 3, 2] },
    { "id": "attic", "min": [10, 0, 10], "max": [13, 3, 13] }
  ],
  "portals": [
    { "id": "scanner", "room": "hall", "kind": "volume", "target": "past", "center": [0, 1.2, 0],
      "normal": [0, 0, 1], "width": 1.0, "height": 2.4, "depth": 0.6 },
    { "id": "hall_east", "room": "hall", "center": [2, 1.1, 0], "normal": [-1, 0, 0],
      "width": 1.0, "height": 2.2, "target": "study_west" },
    { "id": "study_west", "room": "study", "center": [2, 1.1, 0], "normal": [1, 0, 0],
      "width": 1.0, "height": 2.2, "target": "hall_east" },
    { "id": "hall_mirror", "room": "hall", "kind": "mirror", "center": [0, 1.5, -2], "normal": [0, 0, 1],
      "width": 1.0, "height": 1.0 },
    { "id": "hall_west", "room": "hall", "center": [-2, 1.1, 0], "normal": [1, 0, 0],
      "width": 1.0, "height": 2.2, "target": "garden_east" },
    { "id": "garden_east", "room": "garden", "center": [-2, 1.1, 0], "normal": [-1, 0, 0],
      "width": 1.0, "height": 2.2, "target": "hall_west" },
    { "id": "study_south", "room": "study", "center": [3.5, 1, 1.5], "normal": [0, 0, -1],
      "width": 0.8, "height": 2.0, "target": "garden_south" },
    { "id": "garden_south", "room": "garden", "center": [-3.5, 1, 1.5], "normal": [0, 0, -1],
      "width": 0.8, "height": 2.0, "target": "study_south" },
    { "id": "attic_a", "room": "attic", "center": [10, 1.1, 11.5], "normal": [1, 0, 0],
      "width": 1.0, "height": 2.2, "target": "attic_b" },
    { "id": "attic_b", "room": "attic", "center": [13, 1.1, 11.5], "normal": [-1, 0, 0],
      "width": 1.0, "height": 2.2, "target": "attic_a" }
  ],
  "changes": CHANGES
})";

const std::string kSwapEast =
    R"({ "id": "swap_east", "when": { "enter": "study" }, "pairs": [["hall_east", "garden_east"]] })";
const std::string kBack =
    R"({ "id": "back", "when": { "after": "swap_east", "enter": "garden", "time": 2.5 },
      "pairs": [["hall_east", "study_west"], ["hall_west", "garden_east"]] })";

std::string with_changes(const std::string& changes) { return replace_once(kLayout, "CHANGES", changes); }

// The two valid changes, with `from` replaced by `to` (in the first that has it).
std::string two_changes_with(const std::string& from, const std::string& to) {
    return with_changes(replace_once("[\n    " + kSwapEast + ",\n    " + kBack + "\n  ]", from, to));
}

// Loads `text` and expects no error and exactly one warning: at the first
// `needle`, with a message starting with `message_start`.
void expect_one_warning(const std::string& text, const std::string& needle, const std::string& message_start) {
    const LoadResult r = load(text);
    ASSERT_TRUE(r.layout.has_value()) << all_messages(r.errors);
    ASSERT_EQ(r.warnings.size(), 1u) << all_messages(r.warnings);
    const Pos want = position_of(text, needle);
    EXPECT_EQ(r.warnings[0].line, want.line) << r.warnings[0].str();
    EXPECT_EQ(r.warnings[0].column, want.column) << r.warnings[0].str();
    EXPECT_EQ(r.warnings[0].message.substr(0, message_start.size()), message_start) << r.warnings[0].str();
    EXPECT_TRUE(r.loud_warnings.empty()) << all_messages(r.loud_warnings);
}

void expect_no_warnings(const std::string& text) {
    const LoadResult r = load(text);
    ASSERT_TRUE(r.layout.has_value()) << all_messages(r.errors);
    EXPECT_TRUE(r.warnings.empty()) << all_messages(r.warnings);
}

TEST(LayoutChanges, TwoChangesAreReadWithLayoutIndices) {
    const std::string text = two_changes_with("", "");
    expect_no_warnings(text);
    const Layout l = expect_valid(text);
    ASSERT_EQ(l.portals.size(), 9u);
    ASSERT_EQ(l.changes.size(), 2u);
    const Change& swap = l.changes[0];
    EXPECT_EQ(swap.id, "swap_east");
    EXPECT_EQ(swap.when.enter, 1);
    EXPECT_EQ(swap.when.after, -1);
    EXPECT_FALSE(swap.when.time.has_value());
    ASSERT_EQ(swap.pairs.size(), 1u);
    EXPECT_EQ(swap.pairs[0], (std::array<int, 2>{0, 4}));
    EXPECT_EQ(l.portals[0].id, "hall_east");
    EXPECT_EQ(l.portals[4].id, "garden_east");
    const Change& back = l.changes[1];
    EXPECT_EQ(back.id, "back");
    EXPECT_EQ(back.when.enter, 2);
    EXPECT_EQ(back.when.after, 0);
    ASSERT_TRUE(back.when.time.has_value());
    EXPECT_EQ(*back.when.time, 2.5);
    ASSERT_EQ(back.pairs.size(), 2u);
    EXPECT_EQ(back.pairs[0], (std::array<int, 2>{0, 1}));
    EXPECT_EQ(back.pairs[1], (std::array<int, 2>{3, 4}));
    EXPECT_EQ(l.portals[3].id, "hall_west");
    // The layout's own pairing is unchanged by the changes.
    EXPECT_EQ(l.portals[0].target, 1);
    EXPECT_EQ(l.portals[3].target, 4);
}

TEST(LayoutChanges, AbsentOrEmptyMeansNoChanges) {
    const std::string without = replace_once(with_changes("[]"), ",\n  \"changes\": []", "");
    EXPECT_TRUE(expect_valid(without).changes.empty());
    EXPECT_TRUE(expect_valid(with_changes("[]")).changes.empty());
    // A door of the same size in the same room is a fine partner, and a
    // `when` of a time alone.
    const Layout l =
        expect_valid(with_changes(R"([{ "id": "t", "when": { "time": 0 }, "pairs": [["hall_east", "hall_west"]] }])"));
    ASSERT_EQ(l.changes.size(), 1u);
    EXPECT_EQ(l.changes[0].when.enter, -1);
    EXPECT_EQ(l.changes[0].when.time, 0.0);
    EXPECT_EQ(l.changes[0].pairs[0], (std::array<int, 2>{0, 3}));
}

TEST(LayoutChanges, ChangesMustBeAnArrayOfObjects) {
    expect_one_error(with_changes("{}"), "{}", "changes: must be an array (got an object)");
    expect_one_error(with_changes("[ 42 ]"), "42 ]", "changes[0]: must be an object (got a number)");
}

TEST(LayoutChanges, UnknownFieldsAreErrorsAtTheirKey) {
    expect_one_error(two_changes_with("\"pairs\": [[\"hall_east\", \"garden_east\"]]",
                                      "\"pairs\": [[\"hall_east\", \"garden_east\"]], \"note\": 1"),
                     "\"note\"", "changes[0].note: unknown field \"note\"");
    expect_one_error(two_changes_with("{ \"enter\": \"study\" }", "{ \"enter\": \"study\", \"entre\": 1 }"),
                     "\"entre\"", "changes[0].when.entre: unknown field \"entre\" (did you mean \"enter\"?)");
}

TEST(LayoutChanges, IdWhenAndPairsAreRequired) {
    const std::string no_id = two_changes_with("\"id\": \"swap_east\", ", "");
    // Without its id, swap_east cannot be named: "after" is not reported.
    expect_one_error(no_id, "{ \"when\"", "changes[0]: missing required field \"id\"");
    expect_one_error(two_changes_with("\"when\": { \"enter\": \"study\" }, ", ""), "{ \"id\": \"swap_east\"",
                     "changes[0]: missing required field \"when\"");
    expect_one_error(two_changes_with(", \"pairs\": [[\"hall_east\", \"garden_east\"]]", ""), "{ \"id\": \"swap_east\"",
                     "changes[0]: missing required field \"pairs\"");
}

TEST(LayoutChanges, IdsAreUniqueIds) {
    const std::string twice = two_changes_with("\"id\": \"back\"", "\"id\": \"swap_east\"");
    expect_one_error(twice, "\"swap_east\", \"when\"",
                     "changes[1].id: duplicate change id \"swap_east\" (also used by changes[0])", 1);
    expect_one_error(two_changes_with("\"id\": \"back\"", "\"id\": \"a b\""), "\"a b\"",
                     "changes[1].id: id \"a b\" must be letters");
    expect_one_error(two_changes_with("\"id\": \"back\"", "\"id\": 7"), "7, \"when\"",
                     "changes[1].id: must be a string (got a number)");
}

TEST(LayoutChanges, WhenNeedsAtLeastOneField) {
    expect_one_error(two_changes_with("{ \"enter\": \"study\" }", "{ }"), "{ }",
                     "changes[0].when: needs at least one of \"enter\" (a room id), \"after\" (a change id) and "
                     "\"time\" (seconds)");
    expect_one_error(two_changes_with("{ \"enter\": \"study\" }", "{ \"_note\": \"x\" }"), "{ \"_note\"",
                     "changes[0].when: needs at least one of");
    expect_one_error(two_changes_with("{ \"enter\": \"study\" }", "\"study\""), "\"study\", \"pairs\"",
                     "changes[0].when: must be an object (got a string)");
}

TEST(LayoutChanges, EnterNamesARoom) {
    expect_one_error(two_changes_with("\"enter\": \"study\"", "\"enter\": \"cellar\""), "\"cellar\"",
                     "changes[0].when.enter: no room has the id \"cellar\"");
    expect_one_error(two_changes_with("\"enter\": \"study\"", "\"enter\": 17"), "17 }",
                     "changes[0].when.enter: must be a string (got a number)");
}

TEST(LayoutChanges, AfterNamesAnEarlierChange) {
    expect_one_error(two_changes_with("\"after\": \"swap_east\"", "\"after\": \"swap_west\""), "\"swap_west\"",
                     "changes[1].when.after: no change has the id \"swap_west\"");
    expect_one_error(two_changes_with("\"after\": \"swap_east\"", "\"after\": \"back\""), "\"back\", \"enter\"",
                     "changes[1].when.after: names this change itself; \"after\" must name an earlier change "
                     "(changes are considered in file order)");
    // A cycle cannot be written: one of its changes names a later one.
    expect_one_error(two_changes_with("{ \"enter\": \"study\" }", "{ \"enter\": \"study\", \"after\": \"back\" }"),
                     "\"back\" }",
                     "changes[0].when.after: names a later change, changes[1]; \"after\" must name an earlier "
                     "change (changes are considered in file order): move \"back\" before this one");
}

TEST(LayoutChanges, TimeIsSecondsFromZero) {
    expect_one_error(two_changes_with("\"time\": 2.5", "\"time\": -1"), "-1 }",
                     "changes[1].when.time: must not be negative (got -1)");
    expect_one_error(two_changes_with("\"time\": 2.5", "\"time\": \"2.5\""), "\"2.5\"",
                     "changes[1].when.time: must be a number (got a string)");
    expect_one_error(two_changes_with("\"time\": 2.5", "\"time\": 1e7"), "1e7",
                     "changes[1].when.time: 10000000 is too large (the maximum is 1000000 s)");
}

TEST(LayoutChanges, PairsIsANonEmptyListOfTwoDoorIds) {
    expect_one_error(two_changes_with("[[\"hall_east\", \"garden_east\"]]", "[]"), "[] }",
                     "changes[0].pairs: must list at least one pair of door ids");
    expect_one_error(two_changes_with("[[\"hall_east\", \"garden_east\"]]", "[\"hall_east\"]"), "\"hall_east\"] }",
                     "changes[0].pairs[0]: must be an array of 2 door ids (got a string)");
    expect_one_error(two_changes_with("[\"hall_east\", \"garden_east\"]", "[\"hall_east\"]"), "[\"hall_east\"]",
                     "changes[0].pairs[0]: must be an array of 2 door ids (got an array of 1)");
    expect_one_error(two_changes_with("\"garden_east\"]]", "null]]"), "null",
                     "changes[0].pairs[0][1]: must be a string (got null)");
}

TEST(LayoutChanges, PairsNameKnownPortals) {
    expect_one_error(two_changes_with("\"garden_east\"]]", "\"garden_gate\"]]"), "\"garden_gate\"",
                     "changes[0].pairs[0][1]: no portal has the id \"garden_gate\"");
}

TEST(LayoutChanges, OnlyDoorsAreRePaired) {
    expect_one_error(two_changes_with("[[\"hall_east\", \"garden_east\"]]", "[[\"hall_mirror\", \"garden_east\"]]"),
                     "\"hall_mirror\", \"garden_east\"",
                     "changes[0].pairs[0][0]: \"hall_mirror\" is a mirror; a change re-pairs doors only (not "
                     "mirrors, windows or volumes)");
    expect_one_error(two_changes_with("[[\"hall_east\", \"garden_east\"]]", "[[\"hall_east\", \"scanner\"]]"),
                     "\"scanner\"]]", "changes[0].pairs[0][1]: \"scanner\" is a volume; a change re-pairs doors only");
}

TEST(LayoutChanges, WindowsAreNotRePaired) {
    // Two windows of the hall's size in the study and the garden, paired.
    std::string text = two_changes_with("[[\"hall_east\", \"garden_east\"]]", "[[\"hall_east\", \"study_glass\"]]");
    text = replace_once(text, "\"portals\": [",
                        "\"portals\": [\n    { \"id\": \"study_glass\", \"room\": \"study\", \"kind\": \"window\", "
                        "\"center\": [5, 1.2, 0], \"normal\": [-1, 0, 0], \"width\": 1.0, \"height\": 2.2, "
                        "\"target\": \"garden_glass\" },\n    { \"id\": \"garden_glass\", \"room\": \"garden\", "
                        "\"kind\": \"window\", \"center\": [-5, 1.2, 0], \"normal\": [1, 0, 0], \"width\": 1.0, "
                        "\"height\": 2.2, \"target\": \"study_glass\" },");
    expect_one_error(text, "\"study_glass\"]]",
                     "changes[0].pairs[0][1]: \"study_glass\" is a window; a change re-pairs doors only");
}

TEST(LayoutChanges, APairsDoorsHaveTheSameSize) {
    expect_one_error(two_changes_with("[[\"hall_east\", \"garden_east\"]]", "[[\"hall_east\", \"study_south\"]]"),
                     "[\"hall_east\", \"study_south\"]",
                     "changes[0].pairs[0]: the doors \"hall_east\" (1 x 2.2 m) and \"study_south\" (0.8 x 2 m) "
                     "differ in size (the doors of a pair must have the same width and height, within 1e-06 m)");
}

TEST(LayoutChanges, APairNamesTwoDoors) {
    expect_one_error(two_changes_with("[[\"hall_east\", \"garden_east\"]]", "[[\"hall_east\", \"hall_east\"]]"),
                     "\"hall_east\"]]",
                     "changes[0].pairs[0][1]: names the door \"hall_east\" twice (a door cannot target itself)");
}

TEST(LayoutChanges, ADoorIsInAtMostOnePairOfAChange) {
    expect_one_error(two_changes_with("[\"hall_west\", \"garden_east\"]", "[\"garden_east\", \"hall_east\"]"),
                     "\"hall_east\"]] }",
                     "changes[1].pairs[1][1]: the door \"hall_east\" is already in pairs[0] of this change (a door is "
                     "in at most one pair of a change)");
    // In two changes, it is fine.
    expect_valid(two_changes_with("", ""));
}

TEST(LayoutChanges, EveryProblemIsReportedInFileOrder) {
    const std::string text = with_changes(R"([
    { "id": "a", "when": { "enter": "cellar" }, "pairs": [["hall_mirror", "nowhere"]] },
    { "id": "a", "when": { "after": "z" }, "pairs": [["hall_east", "study_south"]] }
  ])");
    const LoadResult r = load(text);
    ASSERT_EQ(r.errors.size(), 6u) << all_messages(r.errors);
    EXPECT_TRUE(has_error(r, position_of(text, "\"cellar\""), "changes[0].when.enter: no room"));
    EXPECT_TRUE(has_error(r, position_of(text, "\"hall_mirror\", \"nowhere\""), "changes[0].pairs[0][0]: "));
    EXPECT_TRUE(has_error(r, position_of(text, "\"nowhere\"]"), "changes[0].pairs[0][1]: no portal"));
    EXPECT_TRUE(has_error(r, position_of(text, "\"a\", \"when\": { \"after\""), "changes[1].id: duplicate"));
    EXPECT_TRUE(has_error(r, position_of(text, "\"z\""), "changes[1].when.after: no change has the id"));
    EXPECT_TRUE(has_error(r, position_of(text, "[\"hall_east\", \"study_south\"]"), "changes[1].pairs[0]: the doors"));
    for (std::size_t i = 1; i < r.errors.size(); ++i) {
        EXPECT_TRUE(r.errors[i - 1].line < r.errors[i].line ||
                    (r.errors[i - 1].line == r.errors[i].line && r.errors[i - 1].column < r.errors[i].column))
            << all_messages(r.errors);
    }
}

TEST(LayoutChanges, EnteringARoomNoDoorReachesIsAWarning) {
    expect_one_warning(with_changes("[" + replace_once(kSwapEast, "\"study\"", "\"attic\"") + "]"), "\"attic\" }",
                       "changes[0].when.enter: this change can never happen: no door leads from the start to the "
                       "room \"attic\" (with the layout's pairs or any change's)");
    // The start's room, and a room only a change's pair reaches, are fine.
    expect_no_warnings(two_changes_with("\"enter\": \"study\"", "\"enter\": \"hall\""));
    expect_no_warnings(two_changes_with(
        "\"pairs\": [[\"hall_east\", \"study_west\"], [\"hall_west\", \"garden_east\"]]",
        "\"pairs\": [[\"hall_east\", \"study_west\"], [\"hall_west\", \"attic_a\"]] }, { \"id\": \"up\", "
        "\"when\": { \"enter\": \"attic\" }, \"pairs\": [[\"attic_b\", \"garden_east\"]]"));
}

TEST(LayoutChanges, WaitingForAChangeThatCanNeverHappenIsAWarning) {
    const std::string text = with_changes(R"([
    { "id": "upstairs", "when": { "enter": "attic" }, "pairs": [["hall_east", "garden_east"]] },
    { "id": "later", "when": { "after": "upstairs" }, "pairs": [["hall_east", "study_west"]] },
    { "id": "last", "when": { "after": "later", "time": 1 }, "pairs": [["hall_west", "study_west"]] }
  ])");
    const LoadResult r = load(text);
    ASSERT_TRUE(r.layout.has_value()) << all_messages(r.errors);
    ASSERT_EQ(r.warnings.size(), 3u) << all_messages(r.warnings);
    const Pos attic = position_of(text, "\"attic\" }");
    const Pos upstairs = position_of(text, "\"upstairs\" }");
    const Pos later = position_of(text, "\"later\", \"time\"");
    EXPECT_EQ(r.warnings[0].line, attic.line);
    EXPECT_EQ(r.warnings[0].column, attic.column);
    EXPECT_EQ(r.warnings[1].line, upstairs.line);
    EXPECT_EQ(r.warnings[1].column, upstairs.column);
    EXPECT_EQ(r.warnings[1].message,
              "changes[1].when.after: this change can never happen: it waits for \"upstairs\", which can never "
              "happen");
    EXPECT_EQ(r.warnings[2].line, later.line);
    EXPECT_EQ(r.warnings[2].column, later.column);
    EXPECT_EQ(r.warnings[2].message,
              "changes[2].when.after: this change can never happen: it waits for \"later\", which can never "
              "happen");
}

TEST(LayoutChanges, RePairingDoorsAsTheyAreIsAWarning) {
    const std::string same = R"([{ "id": "same", "when": { "enter": "study" },
      "pairs": [["garden_east", "hall_west"], ["study_south", "garden_south"]] }])";
    expect_one_warning(with_changes(same), "[[\"garden_east\"",
                       "changes[0].pairs: changes nothing: each of its pairs is already paired so in the layout, and "
                       "no other change re-pairs these doors");
    // One new pair is a change.
    expect_no_warnings(with_changes(replace_once(same, "\"garden_south\"]",
                                                 "\"garden_south\"], "
                                                 "[\"hall_east\", \"attic_a\"]")));
    // A change that restores a pair another change breaks changes
    // something, with or without an `after`.
    expect_no_warnings(two_changes_with("\"after\": \"swap_east\", ", ""));
}

}  // namespace
}  // namespace layout_test
