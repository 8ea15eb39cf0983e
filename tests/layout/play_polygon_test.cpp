// A play area given as a polygon (layout-format.md, top level: `play_area`).
#include "layout_test_util.hpp"

namespace layout_test {
namespace {

const std::string kRect = "\"play_area\": { \"min\": [-2.0, -2.0], \"max\": [2.0, 2.0] },";

std::string with_play_area(const std::string& play_area) {
    return replace_once(two_rooms(), kRect, "\"play_area\": " + play_area + ",");
}

TEST(PlayPolygon, AnLShapeLoads) {
    const Layout l =
        expect_valid(with_play_area("{ \"polygon\": [[-2, -2], [6, -2], [6, 0], [0, 0], [0, 2], [-2, 2]] }"));
    ASSERT_TRUE(l.play_area.has_value());
    EXPECT_EQ(l.play_area->polygon.size(), 6u);
    EXPECT_EQ(l.play_area->min, glm::dvec2(-2, -2));  // the bounding box
    EXPECT_EQ(l.play_area->max, glm::dvec2(6, 2));
    const Summary s = summarize(l);
    EXPECT_DOUBLE_EQ(*s.play_area_area, 8.0 * 2.0 + 2.0 * 2.0);
    // The hall (x -2..2, z -2..2) reaches into the missing corner; the annex (x 2..5, z -1.5..1.5) too.
    EXPECT_EQ(s.rooms_outside_play_area, (std::vector<std::string>{"hall", "annex"}));
}

TEST(PlayPolygon, EitherWindingAndARectangleOutline) {
    const Layout cw = expect_valid(with_play_area("{ \"polygon\": [[-2, -2], [-2, 2], [5, 2], [5, -2]] }"));
    const Summary s = summarize(cw);
    EXPECT_DOUBLE_EQ(*s.play_area_area, 28.0);
    EXPECT_TRUE(s.rooms_outside_play_area.empty());
    EXPECT_EQ(outline(*expect_valid(two_rooms()).play_area).size(), 4u);
}

TEST(PlayPolygon, SelfIntersectionIsAnErrorAtTheCorner) {
    const std::string text = with_play_area("{ \"polygon\": [[-2, -2], [2, 2], [2, -2], [-2, 2]] }");
    expect_one_error(text, "[2, -2]",
                     "play_area.polygon[2]: the play area must be a simple polygon: edge 2 crosses edge 0");
}

TEST(PlayPolygon, RepeatedCornerIsAnError) {
    const std::string text = with_play_area("{ \"polygon\": [[-2, -2], [2, -2], [2, 2], [2, -2], [-2, 2]] }");
    expect_one_error(text, "[2, -2], [-2, 2]]",
                     "play_area.polygon[3]: the play area must be a simple polygon: corner 3 repeats corner 1");
}

TEST(PlayPolygon, FewerThanThreeCornersIsAnError) {
    const std::string text = with_play_area("{ \"polygon\": [[-2, -2], [2, 2]] }");
    expect_one_error(
        text, "[[-2, -2], [2, 2]]",
        "play_area.polygon: the play area must be a simple polygon: a polygon needs at least 3 corners (got 2)");
}

TEST(PlayPolygon, BadCornersAndFields) {
    expect_one_error(with_play_area("{ \"polygon\": [[-2, -2], [2, -2, 1], [0, 2]] }"), "[2, -2, 1]",
                     "play_area.polygon[1]: must be an array of 2 numbers");
    expect_one_error(with_play_area("{ \"polygon\": [[-2, -2], [2, -2], [0, 2]], \"min\": [0, 0] }"), "\"min\": [0, 0]",
                     "play_area.min: unknown field");
    expect_one_error(with_play_area("{ \"polygon\": 3 }"), "3 }", "play_area.polygon: must be an array");
    // All corners on a line: the last edge runs back over the first.
    expect_one_error(with_play_area("{ \"polygon\": [[0, 0], [1, 0], [2, 0]] }"), "[2, 0]",
                     "play_area.polygon[2]: the play area must be a simple polygon: edges 0 and 2 overlap");
}

}  // namespace
}  // namespace layout_test
