// Materials in the rasteriser (issue 13): textured room faces and glTF
// textures, COLOR_0, double-sided and alpha-masked triangles. Layouts are
// built in code, so each test knows which texel lands on which pixel; colours
// are checked against the shading model written out by hand.
#include <cmath>
#include <cstdio>
#include <memory>

#include "cli/view_options.hpp"
#include "gl_fixture.hpp"
#include "image/compare.hpp"
#include "trace/tracer.hpp"

namespace impossible {
namespace {

using testing::id_at;
using testing::pixel;

// The shading model written out (gl_fixture.hpp).
std::array<int, 3> shaded(std::array<double, 3> base, std::array<double, 3> n) {
    return testing::expected_colour(base, n);
}

void expect_near(const image::Image& image, int x, int y, std::array<int, 3> want, const std::string& what) {
    const std::uint8_t* got = pixel(image, x, y);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(int(got[c]), want[c], 1) << what << " at (" << x << ", " << y << ") channel " << c;
}

// A side×side image whose quadrants are red, green (top right), blue (bottom
// left) and yellow; `alpha` per quadrant in the same order.
std::shared_ptr<const image::Pixels> quadrants(int side, std::array<std::uint8_t, 4> alpha = {255, 255, 255, 255}) {
    static constexpr std::uint8_t kRgb[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 0}};
    auto image = std::make_shared<image::Pixels>();
    image->width = image->height = side;
    for (int y = 0; y < side; ++y) {
        for (int x = 0; x < side; ++x) {
            const int q = (y < side / 2 ? 0 : 2) + (x < side / 2 ? 0 : 1);
            image->data.insert(image->data.end(),
                               {kRgb[q][0], kRgb[q][1], kRgb[q][2], alpha[static_cast<std::size_t>(q)]});
        }
    }
    return image;
}

// An 8 m grey cube of a room; the head looks along -z.
layout::Layout grey_room() {
    return testing::layout_from_text(R"({
      "format": "impossible-layout", "version": 1,
      "start": { "room": "r", "position": [0, 1.5, 0] },
      "rooms": [ { "id": "r", "min": [-4, 0, -4], "max": [4, 4, 4], "color": [0.5, 0.5, 0.5] } ] })");
}

render::FrameDesc frame_at(glm::dvec3 head, double pitch_deg, double yaw_deg = 0.0) {
    render::FrameDesc f;
    f.head.position = head;
    f.head.pitch_deg = pitch_deg;
    f.head.yaw_deg = yaw_deg;
    f.eye_width = 65;
    f.eye_height = 49;
    return f;
}

// Pixels of each eye's quadrants: top left, top right, bottom left, bottom right.
constexpr int kQx[4] = {16, 48, 16, 48};
constexpr int kQy[4] = {12, 12, 36, 36};
const std::array<double, 3> kQuadrantRgb[4] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};

TEST(MaterialsRender, FloorTextureTilesFromWholeMultiplesWithItsTopTowardsMinusZ) {
    // One 4 m tile spans x, z in [0, 4]. Looking straight down from (2, 1, 2)
    // with the head's top towards -z, the screen shows the image as it is.
    layout::Layout l = grey_room();
    l.rooms[0].face_texture[0] = quadrants(8);
    l.rooms[0].face_color[0] = glm::dvec3(1.0);
    l.rooms[0].texture_size = 4.0;
    const image::Image image = testing::render_once(gl::Backend::Egl, l, frame_at({2, 1, 2}, -90));
    for (int eye = 0; eye < 2; ++eye)
        for (int q = 0; q < 4; ++q)
            expect_near(image, eye * 65 + kQx[q], kQy[q], shaded(kQuadrantRgb[q], {0, 1, 0}),
                        "floor quadrant " + std::to_string(q));
}

TEST(MaterialsRender, WallTextureReadsUprightAndIsMultipliedByTheFaceColour) {
    // The -z wall (at z = -4) seen from inside: image top up, left on the left.
    layout::Layout l = grey_room();
    l.rooms[0].face_texture[static_cast<int>(layout::Face::NegZ)] = quadrants(8);
    l.rooms[0].face_color[static_cast<int>(layout::Face::NegZ)] = glm::dvec3(0.5, 1.0, 1.0);
    l.rooms[0].texture_size = 4.0;
    const image::Image image = testing::render_once(gl::Backend::Egl, l, frame_at({2, 2, -2.5}, 0));
    for (int eye = 0; eye < 2; ++eye) {
        for (int q = 0; q < 4; ++q) {
            const std::array<double, 3> c = kQuadrantRgb[q];
            expect_near(image, eye * 65 + kQx[q], kQy[q], shaded({0.5 * c[0], c[1], c[2]}, {0, 0, 1}),
                        "wall quadrant " + std::to_string(q));
        }
    }
}

// A 3 m × 2 m quad at z = zq in model coordinates, facing +z, its image's top
// left at (-1.5, 2.5): texture coordinates (0, 0) there and (1, 1) at the
// bottom right.
layout::GltfProp quad_prop(double zq) {
    layout::GltfProp prop;
    prop.path = prop.resolved_path = "<quad>";
    const glm::dvec3 bl(-1.5, 0.5, zq), br(1.5, 0.5, zq), tr(1.5, 2.5, zq), tl(-1.5, 2.5, zq);
    const glm::dvec2 uv_bl(0, 1), uv_br(1, 1), uv_tr(1, 0), uv_tl(0, 0);
    const auto tri = [&](glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, glm::dvec2 ua, glm::dvec2 ub, glm::dvec2 uc) {
        assets::ModelTriangle t;
        t.position = {a, b, c};
        t.normal = {glm::dvec3(0, 0, 1), glm::dvec3(0, 0, 1), glm::dvec3(0, 0, 1)};
        t.uv = {ua, ub, uc};
        t.material = 0;
        prop.triangles.push_back(t);
    };
    tri(bl, br, tr, uv_bl, uv_br, uv_tr);
    tri(bl, tr, tl, uv_bl, uv_tr, uv_tl);
    assets::Material m;
    m.base_color = glm::dvec4(1.0);
    prop.materials.push_back(m);
    for (assets::ModelTriangle& t : prop.triangles) t.color = glm::dvec3(m.base_color);
    return prop;
}

assets::Texture nearest(std::shared_ptr<const image::Pixels> image) {
    assets::Texture t;
    t.image = std::move(image);
    t.sampler.mag_filter = assets::sampler_code::kNearest;
    t.sampler.min_filter = assets::sampler_code::kNearest;
    return t;
}

TEST(MaterialsRender, GltfTextureShowsItsTexelsAtKnownPixels) {
    layout::Layout l = grey_room();
    layout::GltfProp prop = quad_prop(-1.5);
    prop.textures.push_back(nearest(quadrants(2)));
    prop.materials[0].texture = 0;
    l.rooms[0].props.push_back(prop);
    const image::Image image = testing::render_once(gl::Backend::Egl, l, frame_at({0, 1.5, 0}, 0));
    for (int eye = 0; eye < 2; ++eye)
        for (int q = 0; q < 4; ++q)
            expect_near(image, eye * 65 + kQx[q], kQy[q], shaded(kQuadrantRgb[q], {0, 0, 1}),
                        "quad quadrant " + std::to_string(q));
}

TEST(MaterialsRender, VertexColoursMultiplyTheFactor) {
    layout::Layout l = grey_room();
    layout::GltfProp prop = quad_prop(-1.5);
    prop.materials[0].base_color = glm::dvec4(1.0, 0.5, 1.0, 1.0);
    for (assets::ModelTriangle& t : prop.triangles) {
        t.color = glm::dvec3(1.0, 0.5, 1.0);
        for (std::size_t k = 0; k < 3; ++k)  // red on the left edge, blue on the right
            t.vertex_color[k] = t.position[k].x < 0 ? glm::dvec4(0.8, 0.6, 0.2, 1.0) : glm::dvec4(0.2, 0.6, 0.8, 1.0);
    }
    l.rooms[0].props.push_back(prop);
    const image::Image image = testing::render_once(gl::Backend::Egl, l, frame_at({0, 1.5, 0}, 0));
    // Green is 0.6 · 0.5 at every corner, so everywhere; red falls and blue
    // rises from left to right.
    const int green = shaded({0.0, 0.3, 0.0}, {0, 0, 1})[1];
    for (int eye = 0; eye < 2; ++eye) {
        const std::uint8_t* left = pixel(image, eye * 65 + 16, 24);
        const std::uint8_t* right = pixel(image, eye * 65 + 48, 24);
        EXPECT_NEAR(int(left[1]), green, 1);
        EXPECT_NEAR(int(right[1]), green, 1);
        EXPECT_GT(int(left[0]), int(right[0]) + 20);
        EXPECT_LT(int(left[2]) + 20, int(right[2]));
    }
}

TEST(MaterialsRender, DoubleSidedBackIsVisibleMirroredAndLitWithTheReversedNormal) {
    // The quad turned by yaw 180 faces away from the eye: one-sided it is
    // culled (the grey -z wall shows), double-sided its back shows the image
    // mirrored left to right, lit with the normal towards the eye.
    layout::Layout l = grey_room();
    layout::GltfProp prop = quad_prop(1.5);
    prop.yaw_deg = 180.0;
    prop.textures.push_back(nearest(quadrants(2)));
    prop.materials[0].texture = 0;
    l.rooms[0].props.push_back(prop);
    image::Image image = testing::render_once(gl::Backend::Egl, l, frame_at({0, 1.5, 0}, 0));
    expect_near(image, kQx[0], kQy[0], shaded({0.5, 0.5, 0.5}, {0, 0, 1}), "one-sided: the wall behind");

    std::get<layout::GltfProp>(l.rooms[0].props[0]).materials[0].double_sided = true;
    image = testing::render_once(gl::Backend::Egl, l, frame_at({0, 1.5, 0}, 0));
    constexpr int kMirrored[4] = {1, 0, 3, 2};
    for (int eye = 0; eye < 2; ++eye)
        for (int q = 0; q < 4; ++q)
            expect_near(image, eye * 65 + kQx[q], kQy[q], shaded(kQuadrantRgb[kMirrored[q]], {0, 0, 1}),
                        "back quadrant " + std::to_string(q));
}

TEST(MaterialsRender, AlphaMaskCutsHolesWhereFactorTimesTexelIsBelowTheCutoff) {
    // Alpha per quadrant: 1, 0, 1, 128/255; cutoff 0.5.
    layout::Layout l = grey_room();
    layout::GltfProp prop = quad_prop(-1.5);
    prop.textures.push_back(nearest(quadrants(2, {255, 0, 255, 128})));
    prop.materials[0].texture = 0;
    prop.materials[0].alpha_mode = assets::AlphaMode::Mask;
    prop.materials[0].alpha_cutoff = 0.5;
    l.rooms[0].props.push_back(prop);
    const std::array<int, 3> wall = shaded({0.5, 0.5, 0.5}, {0, 0, 1});
    image::Image image = testing::render_once(gl::Backend::Egl, l, frame_at({0, 1.5, 0}, 0));
    for (int eye = 0; eye < 2; ++eye) {
        expect_near(image, eye * 65 + kQx[0], kQy[0], shaded(kQuadrantRgb[0], {0, 0, 1}), "opaque texel");
        expect_near(image, eye * 65 + kQx[1], kQy[1], wall, "alpha 0: the wall behind");
        expect_near(image, eye * 65 + kQx[3], kQy[3], shaded(kQuadrantRgb[3], {0, 0, 1}), "alpha 0.502 >= 0.5");
        EXPECT_EQ(id_at(image, eye * 65 + kQx[1], kQy[1]), 1);
    }
    // A factor alpha of 0.9 puts the last quadrant at 0.45: cut, showing the
    // floor behind it.
    std::get<layout::GltfProp>(l.rooms[0].props[0]).materials[0].base_color.a = 0.9;
    image = testing::render_once(gl::Backend::Egl, l, frame_at({0, 1.5, 0}, 0));
    expect_near(image, kQx[3], kQy[3], shaded({0.5, 0.5, 0.5}, {0, 1, 0}), "alpha 0.45 < 0.5");
    expect_near(image, kQx[0], kQy[0], shaded(kQuadrantRgb[0], {0, 0, 1}), "alpha 0.9");
}

TEST(MaterialsRender, OneDrawPerMaterialStateAndNoneExtraForPlainRooms) {
    // Plain room: 6 faces in one batch. Textured floor, a textured and a
    // masked prop: prop (texture) | prop (masked) | floor | other faces = 4
    // (props first, scene::finish_cell).
    layout::Layout l = grey_room();
    render::FrameStats plain, textured;
    testing::render_once(gl::Backend::Egl, l, frame_at({0, 1.5, 0}, 0), &plain);
    l.rooms[0].face_texture[0] = quadrants(8);
    layout::GltfProp prop = quad_prop(-1.5);
    prop.textures.push_back(nearest(quadrants(2)));
    prop.materials[0].texture = 0;
    assets::Material masked = prop.materials[0];
    masked.alpha_mode = assets::AlphaMode::Mask;
    prop.materials.push_back(masked);
    prop.triangles[1].material = 1;
    l.rooms[0].props.push_back(prop);
    const scene::Scene s = scene::build_scene(l);
    ASSERT_EQ(s.batches[0].size(), 4u);
    EXPECT_EQ(s.batches[0][0].texture, 1);
    EXPECT_LT(s.batches[0][0].alpha_cutoff, 0.0f);
    EXPECT_EQ(s.batches[0][1].texture, 1);
    EXPECT_EQ(s.batches[0][1].alpha_cutoff, 0.5f);
    EXPECT_EQ(s.batches[0][2].texture, 0);
    EXPECT_EQ(s.batches[0][3].texture, -1);
    testing::render_once(gl::Backend::Egl, l, frame_at({0, 1.5, 0}, 0), &textured);
    EXPECT_EQ(textured.draw_calls, plain.draw_calls + 3);
}

TEST(MaterialsRender, StereoModesBackendsAndMultisamplingDrawTheSameMaterials) {
    layout::Layout l = grey_room();
    l.rooms[0].face_texture[0] = quadrants(8);
    l.rooms[0].face_texture[static_cast<int>(layout::Face::NegZ)] = quadrants(16);
    layout::GltfProp prop = quad_prop(-1.5);
    prop.textures.push_back(nearest(quadrants(2, {255, 0, 255, 128})));
    prop.materials[0].texture = 0;
    prop.materials[0].alpha_mode = assets::AlphaMode::Mask;
    prop.materials[0].double_sided = true;
    l.rooms[0].props.push_back(prop);
    render::FrameDesc f = frame_at({0.3, 1.4, 0.5}, -20, 15);
    const image::Image reference = testing::render_once(gl::Backend::Egl, l, f);
    for (const render::StereoMode mode : {render::StereoMode::ViewportIndex, render::StereoMode::TwoPass}) {
        f.stereo = mode;
        const image::Image other = testing::render_once(gl::Backend::Egl, l, f);
        // Texture coordinates interpolate through different float operations
        // per mode, so a pixel on a texel edge may take its neighbour (seen:
        // 1 of 6,370 pixels); untextured surfaces agree exactly.
        EXPECT_LE(testing::count_colour_differences(reference, other), 3) << "stereo mode " << int(mode);
        EXPECT_EQ(testing::count_id_differences(reference, other), 0);
    }
    f.stereo = render::StereoMode::ClipShift;
    EXPECT_EQ(testing::count_colour_differences(reference, testing::render_once(gl::Backend::OSMesa, l, f)), 0);
    f.samples = 4;
    const image::Image msaa = testing::render_once(gl::Backend::Egl, l, f);
    EXPECT_EQ(testing::count_id_differences(reference, msaa), 0);
    // Multisampling changes only edge pixels.
    EXPECT_LT(testing::count_colour_differences(reference, msaa, 8), reference.width * reference.height / 10);
}

}  // namespace
}  // namespace impossible

namespace impossible {
namespace {

// layouts/gallery.json, rendered and traced: ids agree exactly. Colours
// differ where textures are minified, which at 200 × 120 is nearly
// everywhere: the rasteriser filters through mipmaps, the tracer reads mip
// level 0 (docs/tracer.md). With FrameDesc::textures_mip_level0 the rasteriser
// reads mip level 0 too, and the two agree as on untextured layouts; with mipmaps the
// bound is what was measured less a margin (docs/accuracy.md).
struct GalleryPose {
    const char* room;
    glm::dvec3 position;
    double yaw, pitch;
    double min_psnr;  // with mipmaps
    const char* what;
};

TEST(MaterialsRender, GalleryAgreesWithTheTracer) {
    const layout::Layout l = testing::layout_from_file(std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/gallery.json");
    const GalleryPose poses[] = {
        {"hall", {0.3, 1.6, 2.7}, 3, 0, 22.0, "start: brick, tiles, all four models, the studio's murals"},
        {"studio", {0.5, 1.6, -1.0}, 90, -5, 24.0, "through the west door into the garden's cut-out plants"},
        {"hall", {-1.3, 1.0, 1.35}, 0, -35, 25.0, "the crate and a plant close up"},
        {"studio", {0.1, 1.3, 0.6}, 180, -10, 34.0, "the screen's inside (double-sided)"},
    };
    for (const render::ClipMode clip : {render::ClipMode::ClipDistance, render::ClipMode::Oblique}) {
        for (const GalleryPose& p : poses) {
            render::FrameDesc f;
            f.head.position = p.position;
            f.head.yaw_deg = p.yaw;
            f.head.pitch_deg = p.pitch;
            f.room = layout::find_room(l, p.room);
            f.eye_width = 200;
            f.eye_height = 120;
            f.clip = clip;
            const image::Image raster = testing::render_once(gl::Backend::Egl, l, f);
            const image::Image traced = trace::trace_frame(l, cli::trace_desc_for(f)).value();
            ASSERT_FALSE(image::incomparable(raster, traced));
            const image::Comparison cmp = image::compare_pictures(raster, traced);
            std::printf("  gallery %-52s mipmaps %s\n", p.what, image::summary_line(cmp).c_str());
            EXPECT_EQ(cmp.id_mismatch_percent, 0.0) << p.what;
            EXPECT_GE(cmp.interior_psnr_db, p.min_psnr) << p.what;
            f.textures_mip_level0 = true;
            const image::Image level0 = testing::render_once(gl::Backend::Egl, l, f);
            const image::Comparison same_rule = image::compare_pictures(level0, traced);
            std::printf("  gallery %-52s level 0 %s\n", p.what, image::summary_line(same_rule).c_str());
            EXPECT_EQ(same_rule.id_mismatch_percent, 0.0) << p.what;
            EXPECT_GE(same_rule.interior_psnr_db, 40.0) << p.what;
        }
    }
}

}  // namespace
}  // namespace impossible
