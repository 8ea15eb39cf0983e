// Lights (layout-format.md, "Lights"): the top-level `lighting` and
// `light_depth`, each room's `ambient` and `lights`, their defaults and
// limits, and the KHR_lights_punctual lights of glTF props.
#include <cmath>

#include "assets/gltf_model.hpp"
#include "gltf_writer.hpp"
#include "layout_test_util.hpp"

namespace layout_test {
namespace {

// two_rooms.json with "lighting": "lights" (or whatever `top` holds) at the
// top and `hall` (the fields) added to the hall.
std::string lit(const std::string& hall, const std::string& top = "\"lighting\": \"lights\",") {
    std::string text = replace_once(two_rooms(), "\"version\": 1,", "\"version\": 1, " + top);
    if (hall.empty()) return text;
    return replace_once(text, "\"checker\": 0.5,", "\"checker\": 0.5, " + hall + ",");
}

std::string one_light(const std::string& fields) { return lit("\"lights\": [ { " + fields + " } ]"); }

TEST(LayoutLights, AFixedLayoutHasTheDefaults) {
    const Layout l = expect_valid(two_rooms());
    EXPECT_EQ(l.lighting, Lighting::Fixed);
    EXPECT_EQ(l.light_depth, kDefaultLightDepth);
    EXPECT_EQ(l.rooms[0].ambient, kDefaultAmbient);
    EXPECT_TRUE(l.rooms[0].lights.empty());
    const Layout explicit_fixed = expect_valid(lit("", "\"lighting\": \"fixed\","));
    EXPECT_EQ(explicit_fixed.lighting, Lighting::Fixed);
}

TEST(LayoutLights, ALitLayoutReadsAmbientDepthAndLights) {
    const Layout l =
        expect_valid(lit("\"ambient\": [0.2, 0.3, 4], \"lights\": [ "
                         "{ \"position\": [0, 2.6, 0], \"color\": [1.0, 0.9, 0.8], \"intensity\": 6 },"
                         "{ \"position\": [1.5, 2.0, -1], \"intensity\": 20, \"range\": 8, "
                         "\"spot\": { \"direction\": [0, -1.0005, 0], \"inner_deg\": 20, "
                         "\"outer_deg\": 35 } } ]",
                         "\"lighting\": \"lights\", \"light_depth\": 5,"));
    EXPECT_EQ(l.lighting, Lighting::Lights);
    EXPECT_EQ(l.light_depth, 5);
    EXPECT_EQ(l.rooms[0].ambient, glm::dvec3(0.2, 0.3, 4));
    EXPECT_EQ(l.rooms[1].ambient, kDefaultAmbient);
    EXPECT_TRUE(l.rooms[1].lights.empty());
    ASSERT_EQ(l.rooms[0].lights.size(), 2u);
    const Light& a = l.rooms[0].lights[0];
    EXPECT_EQ(a.position, glm::dvec3(0, 2.6, 0));
    EXPECT_EQ(a.color, glm::dvec3(1.0, 0.9, 0.8));
    EXPECT_EQ(a.intensity, 6.0);
    EXPECT_EQ(a.range, 0.0);
    EXPECT_FALSE(a.spot.has_value());
    EXPECT_EQ(a.prop, -1);
    const Light& b = l.rooms[0].lights[1];
    EXPECT_EQ(b.range, 8.0);
    ASSERT_TRUE(b.spot.has_value());
    EXPECT_NEAR(b.spot->direction.y, -1.0, 1e-15);  // normalised, as a portal's normal
    EXPECT_EQ(b.spot->inner_deg, 20.0);
    EXPECT_EQ(b.spot->outer_deg, 35.0);
}

TEST(LayoutLights, ALightsDefaults) {
    const Layout l = expect_valid(one_light("\"position\": [0, 2, 0], \"spot\": { \"direction\": [1, 0, 0] }"));
    ASSERT_EQ(l.rooms[0].lights.size(), 1u);
    const Light& light = l.rooms[0].lights[0];
    EXPECT_EQ(light.color, glm::dvec3(1.0));
    EXPECT_EQ(light.intensity, 1.0);
    EXPECT_EQ(light.range, 0.0);
    EXPECT_EQ(light.spot->inner_deg, 0.0);
    EXPECT_EQ(light.spot->outer_deg, 45.0);
    EXPECT_EQ(l.light_depth, kDefaultLightDepth);
    EXPECT_TRUE(expect_valid(lit("\"lights\": []")).rooms[0].lights.empty());
}

TEST(LayoutLights, LightingMustBeFixedOrLights) {
    expect_one_error(lit("", "\"lighting\": \"sun\","), "\"sun\"", "lighting: must be \"fixed\" or \"lights\"");
    expect_one_error(lit("", "\"lighting\": true,"), "true", "lighting: must be a string");
    // A bad value: the light fields that depend on it are not reported too.
    expect_one_error(lit("\"lights\": [ { \"position\": [0, 9, 0] } ]", "\"lighting\": \"light\", \"light_depth\": 3,"),
                     "\"light\"", "lighting: must be \"fixed\" or \"lights\" (got \"light\")");
}

TEST(LayoutLights, LightFieldsAreErrorsUnderFixed) {
    expect_one_error(lit("", "\"light_depth\": 2,"), "\"light_depth\"",
                     "light_depth: only with \"lighting\": \"lights\"");
    expect_one_error(lit("\"ambient\": [0.1, 0.1, 0.1]", "\"lighting\": \"fixed\","), "\"ambient\"",
                     "rooms[0].ambient: only with \"lighting\": \"lights\"");
    expect_one_error(lit("\"lights\": []", ""), "\"lights\"", "rooms[0].lights: only with \"lighting\": \"lights\"");
}

TEST(LayoutLights, LightDepthIsAJsonIntegerFrom0To16) {
    const std::string lights = "\"lighting\": \"lights\", ";
    EXPECT_EQ(expect_valid(lit("", lights + "\"light_depth\": 0,")).light_depth, 0);
    EXPECT_EQ(expect_valid(lit("", lights + "\"light_depth\": 16,")).light_depth, 16);
    for (const std::string bad : {"17", "-1", "2.0", "2.5", "\"2\"", "1e1"}) {
        const std::string text = lit("", lights + "\"light_depth\": " + bad + ",");
        expect_one_error(text, bad + ",", "light_depth: must be an integer from 0 to 16");
    }
    // Not "(got 2)" for 2.0 (issue 38): the number was written as a decimal.
    expect_one_error(lit("", lights + "\"light_depth\": 2.0,"), "2.0,",
                     "light_depth: must be an integer from 0 to 16 (got a decimal number equal to 2; write 2)");
    expect_one_error(lit("", lights + "\"light_depth\": 2.5,"), "2.5,",
                     "light_depth: must be an integer from 0 to 16 (got 2.5)");
}

TEST(LayoutLights, AmbientIsThreeNumbersAtLeast0) {
    expect_one_error(lit("\"ambient\": [0.1, -0.1, 0.1]"), "-0.1", "rooms[0].ambient[1]: must be at least 0");
    expect_one_error(lit("\"ambient\": [0.1, 0.1]"), "[0.1, 0.1]", "rooms[0].ambient: must be an array of 3 numbers");
    expect_one_error(lit("\"ambient\": [0.1, 0.1, 1e4]"), "1e4", "rooms[0].ambient[2]: 10000 is too large");
}

TEST(LayoutLights, PositionIsRequiredAndStrictlyInsideTheRoom) {
    expect_one_error(one_light("\"intensity\": 2"), "{ \"intensity\"",
                     "rooms[0].lights[0]: missing required field \"position\"");
    // On the ceiling (y = 3): not strictly inside.
    expect_one_error(one_light("\"position\": [0, 3, 0]"), "[0, 3, 0]",
                     "rooms[0].lights[0].position: the light at [0, 3, 0] is not strictly inside its room \"hall\"");
    expect_one_error(one_light("\"position\": [0, 1, 2.0000000001]"), "[0, 1, 2.0000000001]",
                     "rooms[0].lights[0].position: the light at");
    expect_one_error(one_light("\"position\": [-2.000000000001, 1, 0]"), "[-2.000000000001, 1, 0]",
                     "rooms[0].lights[0].position: the light at");
    // 1e-9 · (1 + |p|) from the wall: 1.9999999 is inside, 2 - 1e-9 is not.
    EXPECT_EQ(expect_valid(one_light("\"position\": [1.9999999, 1, 0]")).rooms[0].lights.size(), 1u);
    expect_one_error(one_light("\"position\": [1.999999999, 1, 0]"), "[1.999999999, 1, 0]",
                     "rooms[0].lights[0].position: the light at");
}

TEST(LayoutLights, ColourIntensityAndRange) {
    expect_one_error(one_light("\"position\": [0, 2, 0], \"color\": [1, 1.5, 0]"), "1.5",
                     "rooms[0].lights[0].color[1]: colour component 1.5 is outside 0..1");
    expect_one_error(one_light("\"position\": [0, 2, 0], \"intensity\": 0"), "0 } ]",
                     "rooms[0].lights[0].intensity: must be greater than 0");
    expect_one_error(one_light("\"position\": [0, 2, 0], \"intensity\": -3"), "-3",
                     "rooms[0].lights[0].intensity: must be greater than 0");
    expect_one_error(one_light("\"position\": [0, 2, 0], \"intensity\": 2e9"), "2e9",
                     "rooms[0].lights[0].intensity: 2000000000 is too large");
    expect_one_error(one_light("\"position\": [0, 2, 0], \"range\": 0"), "0 } ]",
                     "rooms[0].lights[0].range: must be greater than 0");
    expect_one_error(one_light("\"position\": [0, 2, 0], \"range\": \"far\""), "\"far\"",
                     "rooms[0].lights[0].range: must be a number");
}

TEST(LayoutLights, TheSpotsRules) {
    const std::string p = "\"position\": [0, 2, 0], ";
    expect_one_error(one_light(p + "\"spot\": { \"inner_deg\": 10 }"), "{ \"inner_deg\"",
                     "rooms[0].lights[0].spot: missing required field \"direction\"");
    expect_one_error(one_light(p + "\"spot\": { \"direction\": [0, 0, 0] }"), "[0, 0, 0]",
                     "rooms[0].lights[0].spot.direction: must not be the zero vector");
    expect_one_error(one_light(p + "\"spot\": { \"direction\": [0, 2, 0] }"), "[0, 2, 0]",
                     "rooms[0].lights[0].spot.direction: must be a unit vector", 1);
    expect_one_error(one_light(p + "\"spot\": { \"direction\": [0, 1, 0], \"inner_deg\": -1 }"), "-1",
                     "rooms[0].lights[0].spot.inner_deg: must be at least 0");
    expect_one_error(one_light(p + "\"spot\": { \"direction\": [0, 1, 0], \"outer_deg\": 91 }"), "91",
                     "rooms[0].lights[0].spot.outer_deg: 91 is too large (the maximum is 90°)");
    expect_one_error(one_light(p + "\"spot\": { \"direction\": [0, 1, 0], \"outer_deg\": 0 }"), "0 } } ]",
                     "rooms[0].lights[0].spot.outer_deg: must be greater than 0");
    expect_one_error(one_light(p + "\"spot\": { \"direction\": [0, 1, 0], \"inner_deg\": 30, \"outer_deg\": 30 }"),
                     "30 } } ]", "rooms[0].lights[0].spot.outer_deg: the cone's outer_deg 30 must be greater than");
    // Without outer_deg, an inner_deg of 45 or more meets the default 45.
    expect_one_error(one_light(p + "\"spot\": { \"direction\": [0, 1, 0], \"inner_deg\": 50 }"), "50",
                     "rooms[0].lights[0].spot.inner_deg: the cone's outer_deg 45 must be greater than");
    const Layout l = expect_valid(one_light(p + "\"spot\": { \"direction\": [0, 1, 0], \"outer_deg\": 90 }"));
    EXPECT_EQ(l.rooms[0].lights[0].spot->outer_deg, 90.0);
}

TEST(LayoutLights, UnknownFieldsAreRefused) {
    expect_one_error(one_light("\"position\": [0, 2, 0], \"colour\": [1, 1, 1]"), "\"colour\"",
                     "rooms[0].lights[0].colour: unknown field \"colour\" (did you mean \"color\"?)");
    expect_one_error(one_light("\"position\": [0, 2, 0], \"spot\": { \"direction\": [0, 1, 0], \"cone\": 3 }"),
                     "\"cone\"", "rooms[0].lights[0].spot.cone: unknown field \"cone\"");
    expect_one_error(lit("\"lights\": [ 3 ]"), "3 ]", "rooms[0].lights[0]: must be an object");
    expect_one_error(lit("\"lights\": { }"), "{ }", "rooms[0].lights: must be an array");
}

TEST(LayoutLights, ALightInsideABoxPropIsAWarning) {
    // The hall's red box spans [-0.3, 0, -0.3]..[0.3, 0.9, 0.3].
    const std::string text = one_light("\"position\": [0, 0.5, 0]");
    const LoadResult r = load(text);
    ASSERT_TRUE(r.errors.empty()) << all_messages(r.errors);
    ASSERT_EQ(r.warnings.size(), 1u);
    const Pos want = position_of(text, "[0, 0.5, 0]");
    EXPECT_EQ(r.warnings[0].line, want.line);
    EXPECT_EQ(r.warnings[0].column, want.column);
    EXPECT_EQ(r.warnings[0].message.rfind("rooms[0].lights[0].position: the light at [0, 0.5, 0] is inside "
                                          "rooms[0].props[0]",
                                          0),
              0u)
        << r.warnings[0].message;
    EXPECT_TRUE(load(one_light("\"position\": [0, 1.5, 0]")).warnings.empty());
}

// A model of one triangle and, on a node moved by `translation` (and turned
// by `rotation`), the KHR_lights_punctual light `light`; written to `name`.
std::string lamp(const std::string& name, const json& light, const json& node_fields = json::object()) {
    GltfWriter w;
    w.node({{"mesh", w.mesh({{"attributes", {{"POSITION", w.vec3(kTriangle)}}}})}});
    json node = {{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}};
    for (auto& [k, v] : node_fields.items()) node[k] = v;
    w.node(node);
    w.doc["extensionsUsed"] = json::array({"KHR_lights_punctual"});
    w.doc["extensions"] = {{"KHR_lights_punctual", {{"lights", json::array({light})}}}};
    const std::string path = temp_path(name);
    w.write(path);
    return path;
}

// A lit two_rooms.json with, in the hall, one written light and the model
// `path` as a prop at `position`, yawed 90° and scaled by 2.
std::string lit_with_lamp(const std::string& path, const std::string& position = "[1, 0.5, 0]",
                          const std::string& top = "\"lighting\": \"lights\",") {
    std::string text = lit("\"lights\": [ { \"position\": [0, 2.5, 0] } ]", top);
    return replace_once(text, "\"color\": [0.9, 0.2, 0.2] }",
                        "\"color\": [0.9, 0.2, 0.2] },\n        { \"gltf\": \"" + path +
                            "\", \"position\": " + position + ", \"yaw_deg\": 90, \"scale\": 2 }");
}

TEST(LayoutLights, AGltfPropsLightsFollowTheWrittenOnesPosedWithTheProp) {
    const json spot = {{"type", "spot"},
                       {"color", {0.5, 0.25, 1}},
                       {"intensity", 40},
                       {"range", 3},
                       {"spot", {{"innerConeAngle", 0.25}, {"outerConeAngle", 0.5}}}};
    // The light's node at (0.5, 0.25, 0) in the model, its -Z turned to -X
    // (90° about +Y).
    const double h = std::sqrt(0.5);
    const std::string path =
        lamp("lamp_spot.gltf", spot, {{"translation", {0.5, 0.25, 0}}, {"rotation", {0, h, 0, h}}});
    const Layout l = expect_valid(lit_with_lamp(path));
    const Room& hall = l.rooms[0];
    ASSERT_EQ(hall.lights.size(), 2u);
    EXPECT_EQ(hall.lights[0].prop, -1);
    const Light& light = hall.lights[1];
    EXPECT_EQ(light.prop, 1);
    ASSERT_EQ(std::get<GltfProp>(hall.props[1]).lights.size(), 1u);
    // Scale 2: (1, 0.5, 0); yaw 90°: (0, 0.5, -1); moved by (1, 0.5, 0).
    EXPECT_NEAR(light.position.x, 1.0, 1e-12);
    EXPECT_NEAR(light.position.y, 1.0, 1e-12);
    EXPECT_NEAR(light.position.z, -1.0, 1e-12);
    // Model -X, yawed 90°: +Z.
    ASSERT_TRUE(light.spot.has_value());
    EXPECT_NEAR(light.spot->direction.x, 0.0, 1e-12);
    EXPECT_NEAR(light.spot->direction.z, 1.0, 1e-12);
    EXPECT_NEAR(light.spot->inner_deg, 0.25 * 180 / M_PI, 1e-9);
    EXPECT_NEAR(light.spot->outer_deg, 0.5 * 180 / M_PI, 1e-9);
    EXPECT_EQ(light.color, glm::dvec3(0.5, 0.25, 1));
    EXPECT_EQ(light.intensity, 40.0);
    EXPECT_EQ(light.range, 3.0);
}

TEST(LayoutLights, AGltfPropsLightsAreIgnoredUnderFixed) {
    const std::string path = lamp("lamp_fixed.gltf", {{"type", "point"}}, {{"translation", {0, 50, 0}}});
    std::string text =
        replace_once(lit_with_lamp(path, "[1, 0.5, 0]", ""), "\"lights\": [ { \"position\": [0, 2.5, 0] } ],", "");
    const Layout l = expect_valid(text);
    EXPECT_TRUE(l.rooms[0].lights.empty());
    EXPECT_TRUE(std::get<GltfProp>(l.rooms[0].props[1]).lights.empty());
}

TEST(LayoutLights, AGltfLightOutsideItsRoomIsDroppedWithAWarningAtTheProp) {
    // 50 m up, scaled by 2: far above the hall's ceiling.
    const std::string path = lamp("lamp_high.gltf", {{"type", "point"}}, {{"translation", {0, 50, 0}}});
    const std::string text = lit_with_lamp(path);
    const LoadResult r = load(text);
    ASSERT_TRUE(r.errors.empty()) << all_messages(r.errors);
    ASSERT_EQ(r.warnings.size(), 1u) << all_messages(r.warnings);
    const Pos want = position_of(text, "{ \"gltf\"");
    EXPECT_EQ(r.warnings[0].line, want.line);
    EXPECT_EQ(r.warnings[0].column, want.column);
    EXPECT_EQ(r.warnings[0].message, "rooms[0].props[1]: the model \"" + path +
                                         "\"'s light 0 (node 1) stands at [1, 100.5, 0], not strictly inside the "
                                         "room \"hall\": it is dropped");
    EXPECT_EQ(r.layout->rooms[0].lights.size(), 1u);  // the written one
}

TEST(LayoutLights, AGltfLightInsideAnotherPropIsAWarningAtItsProp) {
    // Scaled by 2 and moved up 0.2: the light stands at [0, 0.4, 0], inside
    // the hall's red box; the model's own bounds do not count against it.
    const std::string path = lamp("lamp_in_box.gltf", {{"type", "point"}}, {{"translation", {0, 0.1, 0}}});
    const std::string text = lit_with_lamp(path, "[0, 0.2, 0]");
    const LoadResult r = load(text);
    ASSERT_TRUE(r.errors.empty()) << all_messages(r.errors);
    ASSERT_EQ(r.warnings.size(), 1u) << all_messages(r.warnings);
    const Pos want = position_of(text, "{ \"gltf\"");
    EXPECT_EQ(r.warnings[0].line, want.line);
    EXPECT_EQ(r.warnings[0].column, want.column);
    EXPECT_EQ(r.warnings[0].message.rfind(
                  "rooms[0].props[1]: the model's light at [0, 0.4, 0] is inside rooms[0].props[0]", 0),
              0u)
        << r.warnings[0].message;
}

TEST(LayoutLights, DirectionalLightsAreSkippedAndPointsDefault) {
    GltfWriter w;
    w.node({{"mesh", w.mesh({{"attributes", {{"POSITION", w.vec3(kTriangle)}}}})}});
    w.node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    w.node({{"translation", {0, 0.5, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
    w.doc["extensionsUsed"] = json::array({"KHR_lights_punctual"});
    w.doc["extensionsRequired"] = json::array({"KHR_lights_punctual"});
    w.doc["extensions"] = {
        {"KHR_lights_punctual", {{"lights", json::array({{{"type", "directional"}}, {{"type", "point"}}})}}}};
    const std::string path = temp_path("lamp_two.gltf");
    w.write(path);
    const auto model = impossible::assets::load_gltf_model(path, 1000);
    ASSERT_TRUE(model) << model.error();
    ASSERT_EQ(model->lights.size(), 1u);
    const ModelLight& point = model->lights[0];
    EXPECT_EQ(point.position, glm::dvec3(0, 0.5, 0));
    EXPECT_FALSE(point.spot);
    EXPECT_EQ(point.color, glm::dvec3(1.0));
    EXPECT_EQ(point.intensity, 1.0);
    EXPECT_EQ(point.range, 0.0);
}

TEST(LayoutLights, BadGltfLightsAreErrors) {
    const auto error_of = [](const std::string& name, const json& light, const json& node = json::object()) {
        const auto model = impossible::assets::load_gltf_model(lamp(name, light, node), 1000);
        EXPECT_FALSE(model);
        return model ? std::string() : model.error();
    };
    EXPECT_EQ(error_of("bad1.gltf", {{"type", "area"}}).rfind("has light 0 of unknown type \"area\"", 0), 0u);
    EXPECT_EQ(error_of("bad2.gltf", {{"type", "point"}, {"intensity", 0}}).rfind("has light 0 whose intensity 0", 0),
              0u);
    EXPECT_EQ(error_of("bad3.gltf", {{"type", "point"}, {"color", {1, 2, 0}}}).rfind("has light 0 whose color", 0), 0u);
    EXPECT_EQ(error_of("bad4.gltf", {{"type", "spot"}, {"spot", {{"innerConeAngle", 0.5}, {"outerConeAngle", 0.5}}}})
                  .rfind("has light 0 whose cone", 0),
              0u);
    EXPECT_EQ(error_of("bad5.gltf", {{"type", "point"}}, {{"extensions", {{"KHR_lights_punctual", {{"light", 4}}}}}})
                  .rfind("has node 1 whose KHR_lights_punctual light does not exist", 0),
              0u);
    EXPECT_EQ(error_of("bad6.gltf", {{"type", "point"}, {"range", -1}}).rfind("has light 0 whose range -1", 0), 0u);
}

}  // namespace
}  // namespace layout_test
