// Alpha and double-sided glTF materials in the tracer (docs/tracer.md,
// "Materials and textures"): alpha-masked holes that rays pass through, the
// same with and without the tree, and double-sided triangles seen from
// behind with their normal reversed. Colours and textures:
// tracer_material_test.cpp.
#include <gtest/gtest.h>

#include <cstdint>

#include "trace/material_test_util.hpp"
#include "trace/trace_test_util.hpp"
#include "trace/tracer.hpp"

namespace impossible::trace {
namespace {

using glm::dvec4;
using test::add_quad;
using test::bytes_of;
using test::face_color;
using test::kTol;
using test::one_room;
using test::quadrants;
using test::shade_by_hand;
using test::texture;
namespace code = assets::sampler_code;

// The masked quad: its top-right quadrant has alpha `alpha` (the others 1).
layout::Layout masked_quad(std::uint8_t alpha, assets::AlphaMode mode, double base_alpha = 1.0, double cutoff = 0.5) {
    layout::Layout l = one_room();
    layout::GltfProp model;
    assets::Material material;
    material.base_color = {0.6, 0.7, 0.8, base_alpha};
    material.texture = 0;
    material.alpha_mode = mode;
    material.alpha_cutoff = cutoff;
    model.materials.push_back(material);
    model.textures.push_back(texture(quadrants(alpha), code::kNearest));
    add_quad(model, 0);
    l.rooms[0].props.push_back(model);
    return l;
}

TEST(TracerMaterial, MaskedHoleShowsTheWallBehind) {
    const layout::Layout l = masked_quad(0, assets::AlphaMode::Mask);
    const Scene scene = prepare_scene(l).value();
    // Top-right quadrant: through the hole to the -z wall at z = -2.
    const TraceHit hole = trace_ray(scene, {0.5, 2.0, 1.0}, {0, 0, -1}, 0, 8);
    EXPECT_EQ(hole.id, 1);
    EXPECT_NEAR(hole.point.z, -2.0, kTol);
    const dvec3 wall = shade_by_hand(face_color(l.rooms[0], layout::Face::NegZ), {0, 0, 1}, false);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(hole.color[c], wall[c], kTol);
    // The other three: the quad.
    for (const dvec3& o : {dvec3(-0.5, 2.0, 1.0), dvec3(-0.5, 1.0, 1.0), dvec3(0.5, 1.0, 1.0)}) {
        const TraceHit solid = trace_ray(scene, o, {0, 0, -1}, 0, 8);
        EXPECT_NEAR(solid.point.z, -1.0, kTol);
    }
    // Opaque: alpha is not read; the hole is quad.
    const TraceHit opaque =
        trace_ray(prepare_scene(masked_quad(0, assets::AlphaMode::Opaque)).value(), {0.5, 2.0, 1.0}, {0, 0, -1}, 0, 8);
    EXPECT_NEAR(opaque.point.z, -1.0, kTol);
}

TEST(TracerMaterial, MaskCutoffComparesTheWholeAlpha) {
    // Texel alpha 128/255 ≈ 0.502: kept at cutoff 0.5, a hole at cutoff 0.51
    // or when the factor's alpha 0.9 brings it to 0.452.
    const dvec3 origin(0.5, 2.0, 1.0), dir(0, 0, -1);
    EXPECT_NEAR(trace_ray(prepare_scene(masked_quad(128, assets::AlphaMode::Mask)).value(), origin, dir, 0, 8).point.z,
                -1.0, kTol);
    EXPECT_NEAR(
        trace_ray(prepare_scene(masked_quad(128, assets::AlphaMode::Mask, 1.0, 0.51)).value(), origin, dir, 0, 8)
            .point.z,
        -2.0, kTol);
    EXPECT_NEAR(
        trace_ray(prepare_scene(masked_quad(128, assets::AlphaMode::Mask, 0.9)).value(), origin, dir, 0, 8).point.z,
        -2.0, kTol);
    // Exactly at the cutoff is kept (alpha < cutoff is a hole): 0.5 · 1 · 1.
    layout::Layout half = masked_quad(255, assets::AlphaMode::Mask, 0.5, 0.5);
    EXPECT_NEAR(trace_ray(prepare_scene(half).value(), origin, dir, 0, 8).point.z, -1.0, kTol);
}

TEST(TracerMaterial, MaskedFramesAreTheSameWithAndWithoutTheTree) {
    const Scene with = prepare_scene(masked_quad(0, assets::AlphaMode::Mask)).value();
    ASSERT_FALSE(with.rooms[0].bvh.nodes.empty());
    Scene without = with;
    without.rooms[0].bvh = {};
    TraceDesc desc;
    desc.head.position = {0.1, 1.5, 1.0};
    desc.eye_width = 40;
    desc.eye_height = 30;
    const image::Image a = test::expect_same_frames(with, without, desc);
    // The hole shows the -z wall: its colour is in the frame, beside the quad's.
    const auto wall = bytes_of(shade_by_hand(test::make_room("x", {}, {}).face_color[4], {0, 0, 1}, false));
    bool wall_seen = false;
    for (int i = 0; i < a.width && !wall_seen; ++i)
        for (int j = 0; j < a.height && !wall_seen; ++j) wall_seen = test::pixel_rgb(a, i, j) == wall;
    EXPECT_TRUE(wall_seen);
}

// A quad seen from behind (from z = -1.5, looking +z), its vertex normal
// tilted down (0, -0.6, 0.8): from the front that faces away from the light;
// reversed, (0, 0.6, -0.8), it is lit.
Scene tilted_quad(bool double_sided) {
    layout::Layout l = one_room();
    layout::GltfProp model;
    assets::Material material;
    material.base_color = {0.9, 0.5, 0.3, 1.0};
    material.double_sided = double_sided;
    model.materials.push_back(material);
    add_quad(model, 0, dvec4(1.0), {0.0, -0.6, 0.8});
    l.rooms[0].props.push_back(model);
    return prepare_scene(l).value();
}

TraceHit from_behind(bool double_sided) {
    return trace_ray(tilted_quad(double_sided), {0.2, 1.5, -1.5}, {0, 0, 1}, 0, 8);
}

TEST(TracerMaterial, DoubleSidedIsSeenFromBehindWithItsNormalReversed) {
    const TraceHit one = from_behind(false);
    EXPECT_NEAR(one.point.z, 2.0, kTol);  // through it, to the +z wall
    const TraceHit two = from_behind(true);
    EXPECT_EQ(two.id, 1);
    EXPECT_NEAR(two.point.z, -1.0, kTol);
    EXPECT_NEAR(two.normal.y, 0.6, kTol);
    EXPECT_NEAR(two.normal.z, -0.8, kTol);
    const dvec3 lit = shade_by_hand({0.9, 0.5, 0.3}, {0.0, 0.6, -0.8}, false);
    const dvec3 unlit = shade_by_hand({0.9, 0.5, 0.3}, {0.0, -0.6, 0.8}, false);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(two.color[c], lit[c], kTol);
    EXPECT_GT(lit.x, unlit.x + 0.05);  // the reversal shows
    // From the front it is the same triangle with its own normal.
    const TraceHit front = trace_ray(tilted_quad(true), {0.2, 1.5, 1.5}, {0, 0, -1}, 0, 8);
    EXPECT_NEAR(front.point.z, -1.0, kTol);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(front.color[c], unlit[c], kTol);
}

}  // namespace
}  // namespace impossible::trace
