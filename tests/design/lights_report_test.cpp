// validate's report of a lit layout: each room's lights and light paths at
// the layout's light_depth, in the text and the JSON; nothing of it for a
// "fixed" layout, whose report stays as it was.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "design/report.hpp"
#include "layout/layout.hpp"

namespace impossible {
namespace {

// A hall with one light and an annex east of it, joined by a door in x = 2;
// `top` is put at the top level.
std::string lit_hall(const std::string& top) {
    return R"({ "format": "impossible-layout", "version": 1, )" + top + R"(
  "start": { "room": "hall", "position": [0, 1.6, 1] },
  "rooms": [
    { "id": "hall", "min": [-2, 0, -2], "max": [2, 3, 2] LIGHTS },
    { "id": "annex", "min": [2, 0, -1.5], "max": [5, 2.6, 1.5] }
  ],
  "portals": [
    { "id": "e", "room": "hall", "center": [2, 1.1, 0], "normal": [-1, 0, 0], "width": 1, "height": 2.2,
      "target": "w" },
    { "id": "w", "room": "annex", "center": [2, 1.1, 0], "normal": [1, 0, 0], "width": 1, "height": 2.2,
      "target": "e" }
  ] })";
}

design::Report report_of(std::string text, const std::string& lights) {
    text.replace(text.find("LIGHTS"), 6, lights);
    const layout::LoadResult loaded = layout::load_layout_text(text, "hall.json", ".");
    EXPECT_TRUE(loaded.layout) << (loaded.errors.empty() ? "" : loaded.errors[0].str());
    return loaded.layout ? design::make_report(*loaded.layout) : design::Report{};
}

const char* const kOneLight = R"(, "lights": [ { "position": [0, 2, 0], "intensity": 4 } ])";

TEST(LightsReport, CountsEachRoomsLightsAndLightPaths) {
    const std::string text = lit_hall(R"("lighting": "lights",)");
    const design::Report r = report_of(text, kOneLight);
    // The hall's light lights the hall directly and the annex through the door.
    EXPECT_EQ(r.room_lights, (std::vector<int>{1, 0}));
    EXPECT_EQ(r.room_light_paths, (std::vector<int>{1, 1}));
    // With light_depth 0, only the direct path.
    const design::Report direct = report_of(lit_hall(R"("lighting": "lights", "light_depth": 0,)"), kOneLight);
    EXPECT_EQ(direct.room_light_paths, (std::vector<int>{1, 0}));
}

TEST(LightsReport, TheTextAndTheJsonSayIt) {
    std::string text = lit_hall(R"("lighting": "lights",)");
    text.replace(text.find("LIGHTS"), 6, kOneLight);
    const layout::Layout l = *layout::load_layout_text(text, "hall.json", ".").layout;
    const design::Report r = design::make_report(l);
    const std::string out = design::report_text(l, r);
    EXPECT_NE(out.find("lighting: lights, light depth 2\n  hall: 1 light, 1 light path\n  annex: 0 lights, 1 light "
                       "path\nfindings: "),
              std::string::npos)
        << out;
    const nlohmann::ordered_json j = design::report_json(l, r, {});
    EXPECT_EQ(j["lighting"]["light_depth"], 2);
    EXPECT_EQ(j["lighting"]["rooms"][0]["id"], "hall");
    EXPECT_EQ(j["lighting"]["rooms"][0]["lights"], 1);
    EXPECT_EQ(j["lighting"]["rooms"][1]["light_paths"], 1);
}

// A 2 m cube of six windows paired face to face, reflectance 0.5: 1.6
// million light paths from light depth 8 on.
const char* const kWindowCube = R"({ "format": "impossible-layout", "version": 1, "lighting": "lights",
  "light_depth": 16, "start": { "room": "cube", "position": [0, 1, 0] },
  "rooms": [ { "id": "cube", "min": [-1, 0, -1], "max": [1, 2, 1], "lights": [ { "position": [0.3, 1.2, 0.1] } ] } ],
  "portals": [
    { "id": "ax", "room": "cube", "kind": "window", "center": [-1, 1, 0], "normal": [1, 0, 0], "width": 2,
      "height": 2, "reflectance": 0.5, "target": "bx" },
    { "id": "bx", "room": "cube", "kind": "window", "center": [1, 1, 0], "normal": [-1, 0, 0], "width": 2,
      "height": 2, "reflectance": 0.5, "target": "ax" },
    { "id": "ay", "room": "cube", "kind": "window", "center": [0, 0, 0], "normal": [0, 1, 0], "up": [0, 0, 1],
      "width": 2, "height": 2, "reflectance": 0.5, "target": "by" },
    { "id": "by", "room": "cube", "kind": "window", "center": [0, 2, 0], "normal": [0, -1, 0], "up": [0, 0, 1],
      "width": 2, "height": 2, "reflectance": 0.5, "target": "ay" },
    { "id": "az", "room": "cube", "kind": "window", "center": [0, 1, -1], "normal": [0, 0, 1], "width": 2,
      "height": 2, "reflectance": 0.5, "target": "bz" },
    { "id": "bz", "room": "cube", "kind": "window", "center": [0, 1, 1], "normal": [0, 0, -1], "width": 2,
      "height": 2, "reflectance": 0.5, "target": "az" } ] })";

TEST(LightsReport, TooManyLightPathsAreCountedAtALowerDepth) {
    const layout::LoadResult loaded = layout::load_layout_text(kWindowCube, "cube.json", ".");
    ASSERT_TRUE(loaded.layout) << (loaded.errors.empty() ? "" : loaded.errors[0].str());
    const layout::Layout& l = *loaded.layout;
    const design::Report r = design::make_report(l);
    EXPECT_LT(r.light_paths_depth, 16);
    EXPECT_GE(r.light_paths_depth, 1);
    ASSERT_EQ(r.room_light_paths.size(), 1u);
    EXPECT_LE(std::size_t(r.room_light_paths[0]), design::kMaxReportedLightPaths);
    EXPECT_GT(r.room_light_paths[0], 1);
    const std::string text = design::report_text(l, r);
    EXPECT_NE(text.find("lighting: lights, light depth 16\n  light paths: more than 1024 in all rooms together; "
                        "frames are lit at light depth " +
                        std::to_string(r.light_paths_depth) + ", the deepest within that\n  cube: 1 light, "),
              std::string::npos)
        << text;
    const nlohmann::ordered_json j = design::report_json(l, r, {});
    EXPECT_EQ(j["lighting"]["light_paths_truncated"], true);
    EXPECT_EQ(j["lighting"]["light_paths_depth"], r.light_paths_depth);
    // Within the budget, nothing is said.
    const layout::Layout shallow = [&] {
        layout::Layout copy = l;
        copy.light_depth = 2;
        return copy;
    }();
    const design::Report within = design::make_report(shallow);
    EXPECT_EQ(within.light_paths_depth, 2);
    EXPECT_EQ(design::report_text(shallow, within).find("more than"), std::string::npos);
    EXPECT_FALSE(design::report_json(shallow, within, {})["lighting"].contains("light_paths_truncated"));
}

TEST(LightsReport, AFixedLayoutsReportHasNoLighting) {
    std::string text = lit_hall("");
    text.replace(text.find("LIGHTS"), 6, "");
    const layout::Layout l = *layout::load_layout_text(text, "hall.json", ".").layout;
    const design::Report r = design::make_report(l);
    EXPECT_TRUE(r.room_lights.empty());
    EXPECT_EQ(design::report_text(l, r).find("light"), std::string::npos);
    EXPECT_FALSE(design::report_json(l, r, {}).contains("lighting"));
}

}  // namespace
}  // namespace impossible
