// Real glTF lamps (issue 38 §1): alphaMode BLEND loads and is drawn
// alpha-tested at 0.5 (or opaque, by the prop's "blend"), with one warning
// per material; a model's light outside its room and its directional lights
// are dropped with a warning naming them; "lights": false drops them all;
// the top-level "exposure".
#include "assets/gltf_model.hpp"
#include "common/lamp_model.hpp"
#include "layout_test_util.hpp"

namespace layout_test {
namespace {

const std::string& lamp_path() {
    static const std::string path = [] {
        const std::string p = temp_path("lamp_blend.gltf");
        impossible::test::write_lamp_model(p);
        return p;
    }();
    return path;
}

// two_rooms.json, lit unless `top` says otherwise, with the lamp in the hall
// at [1, 0, 1] and `fields` added to its prop.
std::string with_lamp(const std::string& fields = "", const std::string& top = "\"lighting\": \"lights\",") {
    std::string text = replace_once(two_rooms(), "\"version\": 1,", "\"version\": 1, " + top);
    return replace_once(text, "\"color\": [0.9, 0.2, 0.2] }",
                        "\"color\": [0.9, 0.2, 0.2] },\n        { \"gltf\": \"" + lamp_path() +
                            "\", \"position\": [1, 0, 1]" + fields + " }");
}

std::vector<std::string> messages(const std::vector<Diagnostic>& list) {
    std::vector<std::string> out;
    for (const Diagnostic& d : list) out.push_back(d.message);
    return out;
}

TEST(GltfLamps, BlendMaterialsLoadAlphaTestedAtOneHalf) {
    const auto model = load_gltf_model(lamp_path(), 1000);
    ASSERT_TRUE(model) << model.error();
    ASSERT_EQ(model->materials.size(), 2u);
    for (const Material& m : model->materials) {
        EXPECT_TRUE(m.blend);
        EXPECT_EQ(m.alpha_mode, AlphaMode::Mask);
        EXPECT_EQ(m.alpha_cutoff, 0.5);
    }
    EXPECT_EQ(model->materials[0].name, "material 0 (\"Glass\")");
    EXPECT_EQ(model->materials[1].name, "material 1 (\"Frosted\")");
    // The point lights are kept with their names; the directional one is named.
    ASSERT_EQ(model->lights.size(), 2u);
    EXPECT_EQ(model->lights[0].name, "light \"Bulb\" (light 0, node 2 \"BulbNode\")");
    EXPECT_EQ(model->lights[1].name, "light \"Point.002\" (light 1, node 3 \"Fill\")");
    ASSERT_EQ(model->directional_lights.size(), 1u);
    EXPECT_EQ(model->directional_lights[0], "light \"Sun\" (light 2, node 4 \"SunNode\")");
}

TEST(GltfLamps, TheLampValidatesWithAWarningForEachBlendMaterialAndDroppedLight) {
    const std::string text = with_lamp();
    const LoadResult r = load(text);
    ASSERT_TRUE(r.errors.empty()) << all_messages(r.errors);
    const std::string model = "rooms[0].props[1]: the model \"" + lamp_path() + "\"";
    const std::vector<std::string> want = {
        model +
            " has material 0 (\"Glass\") with alphaMode \"BLEND\", drawn alpha-tested at 0.5 (set the prop's "
            "\"blend\" to \"mask\" or \"opaque\" to choose)",
        model +
            " has material 1 (\"Frosted\") with alphaMode \"BLEND\", drawn alpha-tested at 0.5 (set the prop's "
            "\"blend\" to \"mask\" or \"opaque\" to choose)",
        model +
            "'s directional light \"Sun\" (light 2, node 4 \"SunNode\") is dropped (a layout's lights are point "
            "and spot lights; the prop's \"lights\": false drops all of its lights)",
        model +
            "'s light \"Point.002\" (light 1, node 3 \"Fill\") stands at [1, -1, 1], not strictly inside the "
            "room \"hall\": it is dropped",
    };
    EXPECT_EQ(messages(r.warnings), want);
    const Pos at = position_of(text, "{ \"gltf\"");
    for (const Diagnostic& d : r.warnings) {
        EXPECT_EQ(d.line, at.line);
        EXPECT_EQ(d.column, at.column);
    }
    // The same lines for render and trace.
    ASSERT_EQ(r.layout->model_warnings.size(), 4u);
    EXPECT_EQ(r.layout->model_warnings[3], r.warnings[3].str());
    // The bulb is the hall's one light; the materials are cut-outs at 0.5.
    const Room& hall = r.layout->rooms[0];
    ASSERT_EQ(hall.lights.size(), 1u);
    EXPECT_EQ(hall.lights[0].position, glm::dvec3(1, 1.2, 1.4));
    const auto& prop = std::get<GltfProp>(hall.props[1]);
    EXPECT_EQ(prop.materials[0].alpha_mode, AlphaMode::Mask);
    EXPECT_EQ(prop.materials[0].alpha_cutoff, 0.5);
}

TEST(GltfLamps, BlendChoosesMaskOrOpaqueWithoutAWarning) {
    const LoadResult mask = load(with_lamp(", \"blend\": \"mask\", \"lights\": false"));
    ASSERT_TRUE(mask.errors.empty()) << all_messages(mask.errors);
    EXPECT_TRUE(mask.warnings.empty()) << all_messages(mask.warnings);
    EXPECT_EQ(std::get<GltfProp>(mask.layout->rooms[0].props[1]).materials[1].alpha_mode, AlphaMode::Mask);
    EXPECT_TRUE(mask.layout->rooms[0].lights.empty());

    const LoadResult opaque = load(with_lamp(", \"blend\": \"opaque\", \"lights\": false"));
    ASSERT_TRUE(opaque.errors.empty()) << all_messages(opaque.errors);
    EXPECT_TRUE(opaque.warnings.empty()) << all_messages(opaque.warnings);
    EXPECT_TRUE(opaque.layout->model_warnings.empty());
    for (const Material& m : std::get<GltfProp>(opaque.layout->rooms[0].props[1]).materials)
        EXPECT_EQ(m.alpha_mode, AlphaMode::Opaque);
}

TEST(GltfLamps, BadBlendAndLightsValuesAreErrorsAtTheirValues) {
    std::string text = with_lamp(", \"blend\": \"glass\"");
    expect_one_error(text, "\"glass\"", "rooms[0].props[1].blend: must be \"mask\" or \"opaque\" (got \"glass\")");
    text = with_lamp(", \"blend\": 12345");
    expect_one_error(text, "12345", "rooms[0].props[1].blend: must be a string");
    text = with_lamp(", \"lights\": \"no\"");
    expect_one_error(text, "\"no\"", "rooms[0].props[1].lights: must be true or false (got a string)");
}

TEST(GltfLamps, AFixedLayoutWarnsOfBlendOnly) {
    const LoadResult r = load(with_lamp("", ""));
    ASSERT_TRUE(r.errors.empty()) << all_messages(r.errors);
    EXPECT_EQ(r.warnings.size(), 2u) << all_messages(r.warnings);
}

TEST(GltfLamps, ExposureIsReadAndChecked) {
    EXPECT_EQ(expect_valid(two_rooms()).exposure, 0.0);
    const std::string top = replace_once(two_rooms(), "\"version\": 1,", "\"version\": 1, \"exposure\": -2.5,");
    EXPECT_EQ(expect_valid(top).exposure, -2.5);
    for (const char* bad : {"21", "-20.5", "\"2\"", "true"}) {
        const std::string text =
            replace_once(two_rooms(), "\"version\": 1,", std::string("\"version\": 1, \"exposure\": ") + bad + ",");
        expect_one_error(text, bad, "exposure: must be a number of EV from -20 to 20");
    }
}

}  // namespace
}  // namespace layout_test
