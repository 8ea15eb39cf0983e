// The summary of `validate` and `validate --json` for volumes, moving props
// and hands: counted only in layouts that have them, so that the reports of
// other layouts stay as they were.
#include <nlohmann/json.hpp>

#include "design/report.hpp"
#include "design_test_util.hpp"

namespace design_test {
namespace {

// Rooms a and b (b a room for a's volume), optionally a moving prop in a and
// `hands` at the top level.
layout::Layout volume_layout(const std::string& extra_top, bool moving) {
    const std::string prop = moving ? R"(, "props": [{"box": {"min": [1, 0, 1], "max": [2, 1, 2]}, "id": "p",)"
                                      R"( "motion": {"path": [[0, 0, 0, 0], [1, 1, 0, 0]]}}])"
                                    : "";
    const std::string text = "{ \"format\": \"impossible-layout\", \"version\": 1," + extra_top +
                             "\"start\": { \"room\": \"a\", \"position\": [0.5, 1.6, 0.5] },\n"
                             "\"rooms\": [{ \"id\": \"a\", \"min\": [0, 0, 0], \"max\": [4, 3, 4]" +
                             prop +
                             " }, { \"id\": \"b\", \"min\": [0, 0, 0], \"max\": [4, 3, 4] }],\n"
                             "\"portals\": [{ \"id\": \"v\", \"room\": \"a\", \"kind\": \"volume\", \"target\": \"b\", "
                             "\"center\": [2, 1, 2], "
                             "\"normal\": [0, 0, 1], \"width\": 1, \"height\": 1, \"depth\": 1 }] }";
    const layout::LoadResult r = layout::load_layout_text(text, "t.json", ".");
    std::string errors;
    for (const auto& d : r.errors) errors += d.str() + "\n";
    EXPECT_TRUE(r.layout.has_value()) << errors << text;
    return r.layout.value_or(layout::Layout{});
}

TEST(DesignVolumesHands, TheSummaryCountsVolumesAndMovingProps) {
    const layout::Layout l = volume_layout("", true);
    const design::Report r = design::make_report(l);
    EXPECT_EQ(r.summary.portals, 0);
    EXPECT_EQ(r.summary.volumes, 1);
    EXPECT_EQ(r.summary.moving_props, 1);
    const auto j = design::report_json(l, r, {});
    EXPECT_EQ(j["summary"]["volumes"], 1);
    EXPECT_EQ(j["summary"]["moving_props"], 1);
    EXPECT_FALSE(j["summary"].contains("hands"));
    const std::string text = layout::summary_text(l, r.summary);
    EXPECT_NE(text.find("portals: 0\npairs: 0\nvolumes: 1\nmoving props: 1\nplay area: none\n"), std::string::npos)
        << text;
}

TEST(DesignVolumesHands, TheSummaryStatesHandsOtherThanTheDefault) {
    const layout::Layout box =
        volume_layout("\"hands\": {\"box\": [0.1, 0.05, 0.2], \"color\": [0.25, 0.5, 1]},\n", false);
    const design::Report r = design::make_report(box);
    EXPECT_EQ(r.summary.moving_props, 0);
    const auto j = design::report_json(box, r, {});
    EXPECT_FALSE(j["summary"].contains("moving_props"));
    ASSERT_TRUE(j["summary"].contains("hands"));
    EXPECT_EQ(j["summary"]["hands"].dump(), R"({"shape":"box","box":[0.1,0.05,0.2],"color":[0.25,0.5,1.0]})");
    const std::string text = layout::summary_text(box, r.summary);
    EXPECT_NE(text.find("\nhands: a box 0.1 x 0.05 x 0.2 m, colour [0.25, 0.5, 1]\n"), std::string::npos) << text;

    const std::string chair = std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/models/chair.glb";
    const layout::Layout gltf = volume_layout("\"hands\": {\"gltf\": \"" + chair + "\", \"scale\": 0.5},\n", false);
    const design::Report g = design::make_report(gltf);
    EXPECT_EQ(design::report_json(gltf, g, {})["summary"]["hands"].dump(),
              R"({"shape":"gltf","gltf":")" + chair + R"(","scale":0.5})");
    EXPECT_NE(layout::summary_text(gltf, g.summary).find("\nhands: the glTF model " + chair + ", scale 0.5\n"),
              std::string::npos);
    // Writing the default box is the default: no line.
    const layout::Layout standard = volume_layout("\"hands\": {\"box\": [0.08, 0.04, 0.16]},\n", false);
    EXPECT_EQ(layout::summary_text(standard, design::make_report(standard).summary).find("hands"), std::string::npos);
}

TEST(DesignVolumesHands, LayoutsWithoutThemHaveNoSuchKeys) {
    const layout::Layout l =
        load("", "a", room("a", 0, 0, 3, 3) + ", " + room("b", 0, 3, 3, 6), door_pair("a", "b", 1.5, 3));
    const design::Report r = design::make_report(l);
    const auto j = design::report_json(l, r, {});
    for (const char* key : {"volumes", "moving_props", "hands"}) EXPECT_FALSE(j["summary"].contains(key)) << key;
    const std::string text = layout::summary_text(l, r.summary);
    for (const char* word : {"volumes", "moving", "hands"}) EXPECT_EQ(text.find(word), std::string::npos) << text;
}

}  // namespace
}  // namespace design_test
