// Prop meshes: boxes face outwards; glTF triangles are placed, winding kept.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/scene.hpp"
#include "scene_test_helpers.hpp"

namespace impossible::scene::test {
namespace {

TEST(PropMesh, BoxFacesOutwards) {
    layout::Layout l = one_room_layout();
    l.rooms[0].checker = 0.25;
    layout::BoxProp box;
    box.min = {-0.5, 0.0, -0.25};
    box.max = {0.5, 0.75, 0.25};
    box.color = {0.9, 0.2, 0.1};
    l.rooms[0].props.push_back(box);
    const Scene s = build_scene(l);
    ASSERT_EQ(s.cells.size(), 1u);
    ASSERT_EQ(triangles(s, s.cells[0]).size(), 12u + 12u);
    // The prop is an object of its own, drawn before the room's faces.
    ASSERT_EQ(s.objects[0].objects.size(), 1u);
    ASSERT_EQ(s.objects[0].batches.size(), 1u);
    EXPECT_EQ(s.objects[0].batches[0].range.first, s.cells[0].first);
    const std::vector<Triangle> ts = triangles(s, s.objects[0].batches[0].range);
    const glm::dvec3 centre = 0.5 * (box.min + box.max);
    for (const Triangle& t : ts) {
        ASSERT_GT(t.area(), 0.0);
        const glm::dvec3 g = t.geometric_normal();
        EXPECT_GT(glm::dot(g, t.centroid() - centre), 0.0);
        for (const Vertex* v : t.v) {
            EXPECT_NEAR(glm::length(glm::dvec3(v->normal) - g), 0.0, 1e-6);
            EXPECT_EQ(v->color, glm::vec3(box.color));
            EXPECT_EQ(v->checker, 0.0f);
            const glm::dvec3 p(v->position);
            for (int a = 0; a < 3; ++a) {
                EXPECT_TRUE(p[a] == box.min[a] || p[a] == box.max[a]) << "not a box corner";
            }
        }
    }
    EXPECT_DOUBLE_EQ(total_area(ts), 2.0 * (1.0 * 0.75 + 1.0 * 0.5 + 0.75 * 0.5));
    EXPECT_TRUE(closed_and_consistent(ts));
}

layout::GltfProp sample_model() {
    layout::GltfProp prop;
    prop.path = prop.resolved_path = "inline";
    prop.position = {1.0, 0.0, -1.0};
    prop.yaw_deg = 90.0;
    prop.scale = 2.0;
    assets::ModelTriangle t;  // counter-clockwise seen from +z
    t.position = {glm::dvec3(0, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0)};
    t.normal = {glm::dvec3(0, 0, 1), glm::dvec3(0, 0, 1), glm::dvec3(0, 0, 1)};
    t.color = {0.1, 0.2, 0.3};
    prop.triangles.push_back(t);
    t.position = {glm::dvec3(0, 0, 0), glm::dvec3(0, 0, 1), glm::dvec3(0, 1, 0)};  // seen from -x
    t.normal = {glm::dvec3(-1, 0, 0), glm::dvec3(-1, 0, 0), glm::dvec3(-1, 0, 0)};
    t.color = {0.4, 0.5, 0.6};
    prop.triangles.push_back(t);
    return prop;
}

TEST(PropMesh, GltfTrianglesArePlacedWithTheirWinding) {
    layout::Layout l = one_room_layout();
    const layout::GltfProp prop = sample_model();
    l.rooms[0].props.push_back(prop);
    const Scene s = build_scene(l);
    ASSERT_EQ(triangles(s, s.cells[0]).size(), 12u + 2u);
    ASSERT_EQ(s.objects[0].batches.size(), 1u);
    const auto all = triangles(s, s.objects[0].batches[0].range);  // the prop's, in its order
    ASSERT_EQ(all.size(), 2u);
    for (std::size_t k = 0; k < 2; ++k) {
        const Triangle& t = all[k];
        const assets::ModelTriangle& m = prop.triangles[k];
        for (std::size_t c = 0; c < 3; ++c) {
            EXPECT_EQ(t.v[c]->position, glm::vec3(layout::place_model_point(prop, m.position[c])));
            EXPECT_NEAR(glm::length(glm::dvec3(t.v[c]->normal) - layout::place_model_normal(prop, m.normal[c])), 0.0,
                        1e-6);
            EXPECT_EQ(t.v[c]->color, glm::vec3(m.color));
            EXPECT_EQ(t.v[c]->checker, 0.0f);
        }
        // Rotation and uniform scale keep the winding: the front side is
        // still the side the normals point to.
        EXPECT_GT(glm::dot(t.geometric_normal(), glm::dvec3(t.v[0]->normal)), 0.999);
    }
    // Independently: scale 2, yaw 90° (turning left: +x goes to -z), then move.
    const Triangle& first = all[0];
    EXPECT_NEAR(glm::length(first.p(0) - glm::dvec3(1, 0, -1)), 0.0, 1e-6);
    EXPECT_NEAR(glm::length(first.p(1) - glm::dvec3(1, 0, -3)), 0.0, 1e-6);
    EXPECT_NEAR(glm::length(first.p(2) - glm::dvec3(1, 2, -1)), 0.0, 1e-6);
    EXPECT_NEAR(glm::length(glm::dvec3(first.v[0]->normal) - glm::dvec3(1, 0, 0)), 0.0, 1e-6);
}

}  // namespace
}  // namespace impossible::scene::test
