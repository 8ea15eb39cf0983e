// The validate summary: counts, rooms outside the play area, expansion ratio.
#include "layout_test_util.hpp"

namespace layout_test {
namespace {

TEST(LayoutSummary, TwoRooms) {
    const Layout layout = expect_valid(two_rooms());
    const Summary s = summarize(layout);
    EXPECT_EQ(s.rooms, 2);
    EXPECT_EQ(s.portals, 2);
    EXPECT_EQ(s.pairs, 1);
    EXPECT_EQ(s.rooms_outside_play_area, std::vector<std::string>{"annex"});
    EXPECT_DOUBLE_EQ(s.floor_area, 16.0 + 9.0);  // 4 x 4 and 3 x 3
    ASSERT_TRUE(s.play_area_area.has_value());
    EXPECT_DOUBLE_EQ(*s.play_area_area, 16.0);
    ASSERT_TRUE(s.expansion_ratio.has_value());
    EXPECT_DOUBLE_EQ(*s.expansion_ratio, 25.0 / 16.0);
    const std::string text = summary_text(layout, s);
    EXPECT_NE(text.find("name: Two rooms, one doorway\n"), std::string::npos) << text;
    EXPECT_NE(text.find("rooms: 2\n"), std::string::npos) << text;
    EXPECT_NE(text.find("portals: 2\n"), std::string::npos) << text;
    EXPECT_NE(text.find("pairs: 1\n"), std::string::npos) << text;
    EXPECT_NE(text.find("rooms outside the play area: annex\n"), std::string::npos) << text;
    EXPECT_NE(text.find("floor area: 25.00 m2\n"), std::string::npos) << text;
    EXPECT_NE(text.find("expansion ratio: 1.56"), std::string::npos) << text;
}

TEST(LayoutSummary, OverlappingRoomsDoubleTheSpace) {
    const LoadResult r = load_layout_file(kLayoutDir + "/impossible.json");
    ASSERT_TRUE(r.layout.has_value()) << all_messages(r.errors);
    const Summary s = summarize(*r.layout);
    EXPECT_TRUE(s.rooms_outside_play_area.empty());  // rooms exactly on the edge fit
    EXPECT_DOUBLE_EQ(*s.expansion_ratio, 2.0);
    EXPECT_NE(summary_text(*r.layout, s).find("rooms outside the play area: none\n"), std::string::npos);
}

TEST(LayoutSummary, WithoutAPlayAreaThereIsNoRatio) {
    const LoadResult r = load_layout_file(kLayoutDir + "/props.json");
    ASSERT_TRUE(r.layout.has_value()) << all_messages(r.errors);
    const Summary s = summarize(*r.layout);
    EXPECT_EQ(s.rooms, 1);
    EXPECT_EQ(s.portals, 0);
    EXPECT_EQ(s.pairs, 0);
    EXPECT_DOUBLE_EQ(s.floor_area, 36.0);
    EXPECT_FALSE(s.play_area_area.has_value());
    EXPECT_FALSE(s.expansion_ratio.has_value());
    EXPECT_TRUE(s.rooms_outside_play_area.empty());
    EXPECT_NE(summary_text(*r.layout, s).find("expansion ratio: n/a (no play area)\n"), std::string::npos);
}

TEST(LayoutSummary, RoomsPartlyOutsideAreListedInFileOrder) {
    std::string text = replace_once(two_rooms(), "\"min\": [-2.0, -2.0], \"max\": [2.0, 2.0]",
                                    "\"min\": [-1.0, -2.0], \"max\": [6.0, 2.0]");
    Summary s = summarize(expect_valid(text));
    EXPECT_EQ(s.rooms_outside_play_area, std::vector<std::string>{"hall"});  // x from -2 < -1
    EXPECT_DOUBLE_EQ(*s.expansion_ratio, 25.0 / 28.0);
    text =
        replace_once(two_rooms(), "\"min\": [-2.0, -2.0], \"max\": [2.0, 2.0]", "\"min\": [10, 10], \"max\": [11, 11]");
    s = summarize(expect_valid(text));
    EXPECT_EQ(s.rooms_outside_play_area, (std::vector<std::string>{"hall", "annex"}));
}

}  // namespace
}  // namespace layout_test
