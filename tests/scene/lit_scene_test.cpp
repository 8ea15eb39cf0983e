// build_scene under "lighting": "lights" (layout-format.md, "Lights"): the
// scene keeps every room's light images at the layout's light depth and the
// layout, for the renderer; a "fixed" layout keeps nothing of the kind.
#include <gtest/gtest.h>

#include "lights/light_images.hpp"
#include "scene_test_helpers.hpp"

namespace impossible::scene::test {
namespace {

layout::Light lit_scene_lamp(glm::dvec3 position) {
    layout::Light l;
    l.position = position;
    l.intensity = 2.0;
    return l;
}

TEST(LitScene, KeepsTheImagesAtTheLayoutsDepthAndTheLayout) {
    layout::Layout l = one_room_layout();
    l.lighting = layout::Lighting::Lights;
    l.light_depth = 1;
    l.rooms[0].ambient = {0.2, 0.1, 0.05};
    l.rooms[0].lights.push_back(lit_scene_lamp({0.5, 2.5, -0.5}));
    l.rooms[0].lights.push_back(lit_scene_lamp({-1.0, 2.0, 1.0}));
    const Scene scene = build_scene(l);
    EXPECT_EQ(scene.lighting, layout::Lighting::Lights);
    EXPECT_EQ(scene.light_depth, 1);
    ASSERT_EQ(scene.room_lights.size(), 1u);
    EXPECT_EQ(scene.room_lights[0].ambient, glm::dvec3(0.2, 0.1, 0.05));
    ASSERT_EQ(scene.room_lights[0].images.size(), 2u);  // no portal: the two lamps themselves
    EXPECT_EQ(scene.room_lights[0].images[1].position, glm::dvec3(-1.0, 2.0, 1.0));
    ASSERT_NE(scene.lit_layout, nullptr);
    EXPECT_EQ(scene.lit_layout->rooms[0].lights.size(), 2u);
}

TEST(LitScene, AFixedLayoutKeepsNoLights) {
    layout::Layout l = one_room_layout();
    const Scene scene = build_scene(l);
    EXPECT_EQ(scene.lighting, layout::Lighting::Fixed);
    EXPECT_TRUE(scene.room_lights.empty());
    EXPECT_EQ(scene.lit_layout, nullptr);
}

}  // namespace
}  // namespace impossible::scene::test
