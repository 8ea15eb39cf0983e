// Every problem of a file is reported at once, in file order.
#include "layout_test_util.hpp"

namespace layout_test {
namespace {

TEST(LayoutManyErrors, AllProblemsAreReportedInFileOrder) {
    const std::string path = kLayoutDir + "/bad_many.json";
    const LoadResult r = load_layout_file(path);
    EXPECT_FALSE(r.layout.has_value());
    std::vector<std::string> got;
    for (const Diagnostic& d : r.errors) got.push_back(d.str());
    const std::vector<std::string> want = {
        path + ":3:14: version: unsupported version 2 (this program reads version 1)",
        path + ":4:22: start.room: no room has the id \"attic\"",
        path + ":6:59: rooms[0].colour: unknown field \"colour\" (did you mean \"color\"?)",
        path + ":7:13: rooms[1].id: duplicate room id \"hall\" (also used by rooms[0])",
        path + ":7:75: rooms[1].checker: must be greater than 0 (got -1)",
        path + ":10:70: portals[0].normal: must be a unit vector (its length is 2; allowed is 1 ± 0.001)",
        path + ":11:44: portals[0].target: no portal has the id \"nowhere\"",
    };
    EXPECT_EQ(got, want) << all_messages(r.errors);
}

TEST(LayoutManyErrors, ErrorsOnOneLineAreOrderedByColumn) {
    const std::string text =
        "{\"format\": \"x\", \"version\": 3, \"start\": {\"room\": \"r\", \"position\": [0, 1, 0]}, "
        "\"rooms\": [{\"id\": \"r\", \"min\": [0, 0, 0], \"max\": [1, 1, 1], \"color\": [2, 2, 2]}]}";
    const LoadResult r = load(text);
    ASSERT_EQ(r.errors.size(), 5u) << all_messages(r.errors);
    EXPECT_EQ(r.errors[0].message, "format: must be \"impossible-layout\" (got \"x\")");
    EXPECT_EQ(r.errors[1].message, "version: unsupported version 3 (this program reads version 1)");
    EXPECT_EQ(r.errors[2].message, "rooms[0].color[0]: colour component 2 is outside 0..1");
    EXPECT_EQ(r.errors[3].message, "rooms[0].color[1]: colour component 2 is outside 0..1");
    EXPECT_EQ(r.errors[4].message, "rooms[0].color[2]: colour component 2 is outside 0..1");
    for (std::size_t i = 1; i < r.errors.size(); ++i) {
        EXPECT_EQ(r.errors[i].line, 1);
        EXPECT_LT(r.errors[i - 1].column, r.errors[i].column);
    }
}

TEST(LayoutManyErrors, ABrokenPartDoesNotHideTheOthers) {
    // A room with a bad box still has its colour checked, and portals into it
    // still have their own fields checked, without follow-on errors.
    std::string text = replace_once(two_rooms(), "\"max\": [5, 2.6, 1.5]", "\"max\": [5, -2.6, 1.5], \"color\": 3");
    text = replace_once(text, "\"width\": 1.0, \"height\": 2.2,\n      \"target\": \"hall_east\"",
                        "\"width\": 1.0, \"height\": \"tall\",\n      \"target\": \"hall_east\"");
    const LoadResult r = load(text);
    ASSERT_EQ(r.errors.size(), 3u) << all_messages(r.errors);
    EXPECT_EQ(r.errors[0].message.rfind("rooms[1].max: must be greater than min on every axis (y: -2.6 <= 0)", 0), 0u);
    EXPECT_EQ(r.errors[1].message, "rooms[1].color: must be an array of 3 numbers [r, g, b] (got a number)");
    EXPECT_EQ(r.errors[2].message, "portals[1].height: must be a number (got a string)");
}

}  // namespace
}  // namespace layout_test
