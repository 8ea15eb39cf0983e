// glTF materials and textured room faces in the tracer (docs/tracer.md,
// "Materials and textures"): base colour · COLOR_0 · texel, read at level 0
// with the mag filter; and room face textures oriented as layout-format.md
// says. Alpha masks and double-sided triangles: tracer_alpha_test.cpp.
// Layouts are built in code and the expected colours are worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <memory>

#include "trace/material_test_util.hpp"
#include "trace/trace_test_util.hpp"
#include "trace/tracer.hpp"

namespace impossible::trace {
namespace {

using glm::dvec2;
using glm::dvec4;
using test::add_quad;
using test::bytes_of;
using test::image_of;
using test::kTol;
using test::one_room;
using test::quadrant;
using test::quadrants;
using test::shade_by_hand;
using test::texture;
namespace code = assets::sampler_code;

// The quad's texel quadrant (column, row) at a point of it; false within
// `margin` of its edges or of the quadrants' boundaries.
bool quad_quadrant(const dvec3& p, double margin, int& i, int& j) {
    if (!(std::abs(p.x) < 1.0 - margin && p.y > 0.5 + margin && p.y < 2.5 - margin)) return false;
    if (std::abs(p.x) < margin || std::abs(p.y - 1.5) < margin) return false;
    i = p.x < 0.0 ? 0 : 1;
    j = p.y > 1.5 ? 0 : 1;  // the image's top row is up
    return true;
}

TEST(TracerMaterial, TexturedQuadShowsFactorTimesColor0TimesTexelAtEveryPixel) {
    layout::Layout l = one_room();
    layout::GltfProp model;
    assets::Material material;
    material.base_color = {0.9, 0.8, 0.7, 1.0};
    material.texture = 0;
    model.materials.push_back(material);
    model.textures.push_back(texture(quadrants(), code::kNearest));
    const dvec4 vertex(0.5, 1.0, 0.8, 1.0);
    add_quad(model, 0, vertex);
    l.rooms[0].props.push_back(model);

    TraceDesc desc;
    desc.head.position = {0.0, 1.5, 1.0};
    desc.eye_width = 33;
    desc.eye_height = 33;
    const image::Image image = trace_frame(l, desc).value();
    int checked = 0;
    int seen[2][2] = {{0, 0}, {0, 0}};
    for (int eye = 0; eye < 2; ++eye) {
        for (int j = 0; j < desc.eye_height; ++j) {
            for (int i = 0; i < desc.eye_width; ++i) {
                const PixelRay ray = pixel_ray(desc, eye, i, j);
                const dvec3 p = ray.origin + ((-1.0 - ray.origin.z) / ray.dir.z) * ray.dir;
                int qi = 0, qj = 0;
                if (!quad_quadrant(p, 0.02, qi, qj)) continue;
                const dvec3 base = dvec3(material.base_color) * dvec3(vertex) * dvec3(quadrant(qi, qj));
                EXPECT_EQ(test::pixel_rgb(image, eye * desc.eye_width + i, j),
                          bytes_of(shade_by_hand(base, {0, 0, 1}, false)))
                    << "eye " << eye << " pixel " << i << ", " << j << " quadrant " << qi << ", " << qj;
                EXPECT_EQ(test::pixel_id(image, eye * desc.eye_width + i, j), 1);
                ++checked;
                ++seen[qi][qj];
            }
        }
    }
    EXPECT_GT(checked, 300);
    for (auto& column : seen)
        for (int n : column) EXPECT_GT(n, 50);
}

TEST(TracerMaterial, Color0AndUvAreBlendedWithTheHitsBarycentrics) {
    layout::Layout l = one_room();
    layout::GltfProp model;
    assets::Material material;
    material.base_color = {0.5, 0.75, 1.0, 1.0};
    material.texture = 0;
    model.materials.push_back(material);
    model.textures.push_back(texture(quadrants(), code::kNearest));
    assets::ModelTriangle t;
    t.position = {dvec3(0, 1, -1), dvec3(1, 1, -1), dvec3(0, 2, -1)};  // facing +z
    t.normal = {dvec3(0, 0, 1), dvec3(0, 0, 1), dvec3(0, 0, 1)};
    t.vertex_color = {dvec4(1.0, 0.5, 0.2, 1.0), dvec4(0.2, 1.0, 0.6, 1.0), dvec4(0.6, 0.4, 1.0, 1.0)};
    t.uv = {dvec2(0.0, 0.0), dvec2(2.0, 0.0), dvec2(0.0, 2.0)};
    t.material = 0;
    model.triangles.push_back(t);
    l.rooms[0].props.push_back(model);
    const Scene scene = prepare_scene(l).value();

    // Weights 1/2, 1/4, 1/4 (vertex 0, 1, 2): uv (1/2, 1/2), texel (1, 1).
    const TraceHit a = trace_ray(scene, {0.25, 1.25, 0.5}, {0, 0, -1}, 0, 8);
    const dvec4 vertex_a = 0.5 * t.vertex_color[0] + 0.25 * t.vertex_color[1] + 0.25 * t.vertex_color[2];
    const dvec3 expected_a =
        shade_by_hand(dvec3(material.base_color) * dvec3(vertex_a) * dvec3(quadrant(1, 1)), {0, 0, 1}, false);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a.color[c], expected_a[c], kTol);
    // Weights 0.8, 0.1, 0.1: uv (0.2, 0.2), texel (0, 0).
    const TraceHit b = trace_ray(scene, {0.1, 1.1, 0.5}, {0, 0, -1}, 0, 8);
    const dvec4 vertex_b = 0.8 * t.vertex_color[0] + 0.1 * t.vertex_color[1] + 0.1 * t.vertex_color[2];
    const dvec3 expected_b =
        shade_by_hand(dvec3(material.base_color) * dvec3(vertex_b) * dvec3(quadrant(0, 0)), {0, 0, 1}, false);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(b.color[c], expected_b[c], kTol);
    // Weights 0.2, 0.1, 0.7: uv (0.2, 1.4), t wraps (repeat) to 0.4, texel (0, 0).
    const TraceHit c = trace_ray(scene, {0.1, 1.7, 0.5}, {0, 0, -1}, 0, 8);
    const dvec4 vertex_c = 0.2 * t.vertex_color[0] + 0.1 * t.vertex_color[1] + 0.7 * t.vertex_color[2];
    const dvec3 expected_c =
        shade_by_hand(dvec3(material.base_color) * dvec3(vertex_c) * dvec3(quadrant(0, 0)), {0, 0, 1}, false);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(c.color[k], expected_c[k], kTol);
}

TEST(TracerMaterial, LinearMagFilterBlendsNeighbours) {
    layout::Layout l = one_room();
    layout::GltfProp model;
    assets::Material material;
    material.base_color = {1.0, 1.0, 1.0, 1.0};
    material.texture = 0;
    model.materials.push_back(material);
    model.textures.push_back(texture(quadrants(), code::kLinear));
    add_quad(model, 0);
    l.rooms[0].props.push_back(model);
    // The quad's centre (s, t) = (1/2, 1/2): the four texels equally.
    const TraceHit hit = trace_ray(prepare_scene(l).value(), {0.0, 1.5, 0.5}, {0, 0, -1}, 0, 8);
    const dvec4 mean = 0.25 * (quadrant(0, 0) + quadrant(1, 0) + quadrant(0, 1) + quadrant(1, 1));
    const dvec3 expected = shade_by_hand(dvec3(mean), {0, 0, 1}, false);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(hit.color[c], expected[c], kTol);
}

// Room faces: a 2 × 2 image on a room [0, 4] × [0, 3] × [0, 4], one tile per
// 2 m, checker side 1. Each face is looked at from the room's middle, and
// the texel centres of the image's top-left, top-right and bottom-left
// quadrants are found where the spec's wording puts them (not through
// room_texture_uv): on walls the image's top is up and its left is on the
// left of a viewer inside facing the wall; on the floor and ceiling its top
// is towards -z.
struct FaceCase {
    layout::Face face;
    dvec3 normal;                            // into the room
    dvec3 top_left, top_right, bottom_left;  // texel centres on the face
};

TEST(TracerMaterial, RoomFaceTexturesAreOrientedAsTheSpecSays) {
    layout::Layout l = one_room({0, 0, 0}, {4, 3, 4});
    layout::Room& room = l.rooms[0];
    room.checker = 1.0;
    room.texture_size = 2.0;
    for (auto& t : room.face_texture) t = quadrants();
    const Scene scene = prepare_scene(l).value();
    const dvec3 eye(2.0, 1.6, 2.0);
    // Texel centres lie at 1/4 and 3/4 of a 2 m tile: 0.5 and 1.5 m past a
    // multiple of 2 m (s and t counted from the image's top-left corner).
    const FaceCase cases[] = {
        // Floor, looking down (top towards -z, left towards -x).
        {layout::Face::Floor, {0, 1, 0}, {0.5, 0, 0.5}, {1.5, 0, 0.5}, {0.5, 0, 1.5}},
        // Ceiling, seen from below: top still towards -z; s grows towards -x.
        {layout::Face::Ceiling, {0, -1, 0}, {1.5, 3, 0.5}, {0.5, 3, 0.5}, {1.5, 3, 1.5}},
        // -z wall, facing it (looking -z): right is +x, up is +y; a tile's
        // top edge is at y = 2 (t = -y / 2 is whole there).
        {layout::Face::NegZ, {0, 0, 1}, {0.5, 1.5, 0}, {1.5, 1.5, 0}, {0.5, 0.5, 0}},
        // +x wall, facing it (looking +x): right is +z.
        {layout::Face::PosX, {-1, 0, 0}, {4, 1.5, 0.5}, {4, 1.5, 1.5}, {4, 0.5, 0.5}},
        // -x wall, facing it (looking -x): right is -z.
        {layout::Face::NegX, {1, 0, 0}, {0, 1.5, 3.5}, {0, 1.5, 2.5}, {0, 0.5, 3.5}},
        // +z wall, facing it (looking +z): right is -x.
        {layout::Face::PosZ, {0, 0, -1}, {3.5, 1.5, 4}, {2.5, 1.5, 4}, {3.5, 0.5, 4}},
    };
    for (const FaceCase& fc : cases) {
        const int i_face = static_cast<int>(fc.face);
        const std::pair<dvec3, dvec4> points[] = {
            {fc.top_left, quadrant(0, 0)}, {fc.top_right, quadrant(1, 0)}, {fc.bottom_left, quadrant(0, 1)}};
        for (const auto& [p, texel] : points) {
            const TraceHit hit = trace_ray(scene, eye, p - eye, 0, 8);
            EXPECT_EQ(hit.id, 1);
            EXPECT_EQ(hit.normal, fc.normal) << layout::kFaceNames[i_face];
            // The checker by hand: the two in-plane coordinates' squares.
            double a = p.x, b = p.z;
            if (fc.normal.x != 0.0) a = p.y;
            if (fc.normal.z != 0.0) b = p.y;
            const bool dark = (static_cast<int>(std::floor(a)) + static_cast<int>(std::floor(b))) % 2 != 0;
            const dvec3 expected = shade_by_hand(room.face_color[i_face] * dvec3(texel), fc.normal, dark);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(hit.color[c], expected[c], 1e-9)
                    << layout::kFaceNames[i_face] << " at " << p.x << ", " << p.y << ", " << p.z;
        }
    }
}

TEST(TracerMaterial, WhiteTexturesAndColor0ChangeNoByte) {
    // A prop and faces textured white, COLOR_0 white: the same frame as
    // without any texture (texels multiply by exactly 1).
    auto build = [](bool textured) {
        layout::Layout l = one_room();
        l.rooms[0].checker = 0.5;
        layout::GltfProp model;
        assets::Material material;
        material.base_color = {0.8, 0.8, 0.8, 1.0};
        if (textured) {
            material.texture = 0;
            model.textures.push_back(texture(image_of(1, 1, {255, 255, 255, 255}), code::kLinear));
            for (auto& t : l.rooms[0].face_texture) t = image_of(2, 1, {255, 255, 255, 255, 255, 255, 255, 255});
        }
        model.materials.push_back(material);
        add_quad(model, textured ? 0 : -1, dvec4(1.0), glm::normalize(dvec3(0.2, 0.3, 1.0)));
        l.rooms[0].props.push_back(model);
        return l;
    };
    TraceDesc desc;
    desc.head.position = {0.3, 1.4, 1.2};
    desc.head.yaw_deg = 10.0;
    desc.eye_width = 48;
    desc.eye_height = 32;
    const image::Image plain = trace_frame(build(false), desc).value(), white = trace_frame(build(true), desc).value();
    EXPECT_EQ(plain.rgb, white.rgb);
    EXPECT_EQ(plain.ids, white.ids);
}

TEST(TracerMaterial, BadMaterialOrTextureIndicesAreErrors) {
    layout::Layout l = one_room();
    layout::GltfProp model;
    add_quad(model, -1);
    model.triangles[0].material = 0;  // no materials
    l.rooms[0].props.push_back(model);
    ASSERT_FALSE(prepare_scene(l));
    EXPECT_NE(prepare_scene(l).error().find("a triangle names no material of the model"), std::string::npos);
    auto& prop = std::get<layout::GltfProp>(l.rooms[0].props[0]);
    prop.materials.emplace_back();
    prop.materials[0].texture = 0;  // no textures
    ASSERT_FALSE(prepare_scene(l));
    EXPECT_NE(prepare_scene(l).error().find("a material names no texture of the model"), std::string::npos);
    prop.materials[0].texture = -1;
    EXPECT_TRUE(prepare_scene(l));
}

}  // namespace
}  // namespace impossible::trace
