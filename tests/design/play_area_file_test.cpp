// The play-area file of `generate --play-area-file` (design/play_area_file.hpp):
// its three forms, and unknown fields refused where they are.
#include "design_test_util.hpp"

#include "design/play_area_file.hpp"

namespace design_test {
namespace {

const math::Polygon2 kSquare = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};

std::string error_of(const std::string& text) {
    const auto r = design::parse_play_area_file(text, "f.json");
    return r ? std::string("no error") : r.error();
}

TEST(PlayAreaFile, ReadsItsThreeForms) {
    const std::string corners = "[[0, 0], [4, 0], [4, 4], [0, 4]]";
    for (const std::string& text :
         {corners, "{\"polygon\": " + corners + ", \"_note\": \"a comment\"}",
          "{\"format\": \"impossible-layout\", \"version\": 1, \"name\": \"n\", \"start\": {},"
          " \"rooms\": [], \"portals\": [], \"play_area\": {\"polygon\": " +
              corners + "}}"}) {
        const auto r = design::parse_play_area_file(text, "f.json");
        ASSERT_TRUE(r.has_value()) << text << ": " << r.error();
        EXPECT_EQ(*r, kSquare);
    }
}

TEST(PlayAreaFile, RefusesUnknownFieldsAtTheirKeys) {
    EXPECT_EQ(error_of("{\"polygon\": [[0, 0], [4, 0], [4, 4]],\n  \"corners\": 3}"),
              "f.json:2:3: corners: unknown field \"corners\"");
    EXPECT_EQ(error_of("{\"polgon\": [[0, 0], [4, 0], [4, 4]]}"),
              "f.json:1:2: polgon: unknown field \"polgon\" (did you mean \"polygon\"?)");
    EXPECT_EQ(error_of("{\"play_area\": {\"polygon\": [[0, 0], [4, 0], [4, 4]], \"scale\": 2}}"),
              "f.json:1:53: play_area.scale: unknown field \"scale\"");
    EXPECT_EQ(error_of("{\"romos\": [], \"play_area\": {\"polygon\": [[0, 0], [4, 0], [4, 4]]}}"),
              "f.json:1:2: romos: unknown field \"romos\" (did you mean \"rooms\"?)");
}

TEST(PlayAreaFile, OtherProblemsAreOneLineEach) {
    EXPECT_EQ(error_of("[[0, 0], [4, 0],\n [4, 4]"),
              "f.json:2:8: invalid JSON: syntax error while parsing array - unexpected end of input; expected ']'");
    EXPECT_EQ(error_of("{\"play_area\": {\"min\": [0, 0], \"max\": [4, 4]}}"),
              "f.json: expected a polygon, [[x, z], ...]");
    EXPECT_EQ(error_of("[[0, 0], [4, 0], [4]]"), "f.json: every corner must be [x, z]");
    EXPECT_EQ(error_of("[[0, 0], [4, 0], [0, 4], [4, 4]]").rfind("f.json: the play area must be a simple polygon", 0),
              0u);
}

}  // namespace
}  // namespace design_test
