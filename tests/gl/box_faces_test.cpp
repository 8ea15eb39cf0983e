// Back faces of box props left out on the CPU (render/objects/box_faces.hpp): fewer
// triangles, the same image, pixel for pixel, for every eye a level can have
// (both eyes, virtual eyes behind doors, mirrored views) and every way of
// drawing it.
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "gl_fixture.hpp"
#include "render/objects/box_faces.hpp"

namespace impossible {
namespace {

struct BfRenderer {
    std::optional<gl::Context> context;
    std::optional<render::Renderer> renderer;
};

std::unique_ptr<BfRenderer> bf_renderer(const layout::Layout& l) {
    auto out = std::make_unique<BfRenderer>();
    Result<gl::Context> context = gl::create_context(gl::Backend::Egl);
    EXPECT_TRUE(context.has_value()) << context.error();
    if (!context) return nullptr;
    out->context.emplace(std::move(*context));
    Result<render::Renderer> r = render::Renderer::create(out->context->state(), scene::build_scene(l));
    EXPECT_TRUE(r.has_value()) << r.error();
    if (!r) return nullptr;
    out->renderer.emplace(std::move(*r));
    return out;
}

// Renders f with and without the boxes' back faces; expects the same image
// and ids and no more triangles. Returns (with, without) triangles.
std::pair<long, long> bf_compare(render::Renderer& renderer, render::FrameDesc f, const std::string& what) {
    f.cull_box_faces = true;
    Result<render::RenderedFrame> culled = renderer.render(f);
    f.cull_box_faces = false;
    Result<render::RenderedFrame> all = renderer.render(f);
    EXPECT_TRUE(culled.has_value() && all.has_value()) << what;
    if (!culled || !all) return {0, 0};
    EXPECT_EQ(testing::count_colour_differences(culled->image, all->image), 0) << what;
    EXPECT_EQ(testing::count_id_differences(culled->image, all->image), 0) << what;
    EXPECT_LE(culled->stats.triangles, all->stats.triangles) << what;
    return {culled->stats.triangles, all->stats.triangles};
}

TEST(BoxFaces, TheBoxesOfSixRoomsThroughDoorsTakeFarFewerTrianglesForTheSameImage) {
    const layout::Layout l = testing::crowded_vr_study(150);
    auto r = bf_renderer(l);
    ASSERT_TRUE(r);
    long with = 0, without = 0;
    for (int k = 0; k < 6; ++k) {
        render::FrameDesc f;
        f.room = l.start.room;
        f.head.position = l.start.position + glm::dvec3(0.2 * (k % 3) - 0.2, 0.0, 0.15 * (k % 2));
        f.head.yaw_deg = 60.0 * k;
        f.head.pitch_deg = -10.0 + 5.0 * (k % 4);
        f.eye_width = 160;
        f.eye_height = 90;
        f.max_depth = 4;
        const auto [a, b] = bf_compare(*r->renderer, f, "pose " + std::to_string(k));
        with += a;
        without += b;
    }
    // A box shows at most three faces to one eye; the two eyes rarely see
    // a fourth. The rooms' own faces and the doors are a few hundred.
    EXPECT_LT(with * 10, without * 6) << with << " of " << without;
}

TEST(BoxFaces, EveryStereoClipDepthSampleAndPortalTextureModeDrawsTheSameImage) {
    const layout::Layout l = testing::crowded_vr_study(60);
    auto r = bf_renderer(l);
    ASSERT_TRUE(r);
    for (int mode = 0; mode < 7; ++mode) {
        render::FrameDesc f;
        f.room = l.start.room;
        f.head.position = l.start.position + glm::dvec3(0.1, -0.4, 0.1);
        f.head.yaw_deg = 25.0 + 70.0 * mode;
        f.head.pitch_deg = -25.0;
        f.eye_width = 160;
        f.eye_height = 90;
        f.max_depth = 3;
        if (mode == 1) f.stereo = render::StereoMode::TwoPass;
        if (mode == 2) f.stereo = render::StereoMode::ViewportIndex;
        if (mode == 3) f.clip = render::ClipMode::Oblique;
        if (mode == 4) f.depth = render::DepthMode::Standard;
        if (mode == 5) f.samples = 4;
        if (mode == 6) f.portal_texture_scale = 0.5;  // the doors' views drawn into textures
        const auto [a, b] = bf_compare(*r->renderer, f, "mode " + std::to_string(mode));
        EXPECT_LT(a, b) << "mode " << mode;
    }
}

TEST(BoxFaces, EveryExampleLayoutWithBoxesDrawsTheSameImageMirrorsIncluded) {
    // Every example layout with box props (in sliding_box.json the box moves:
    // a dynamic object, drawn as before).
    for (const char* name :
         {"corridor.json", "corridor_wall.json", "crossing.json", "default.json", "four_rooms.json",
          "glass_gallery.json", "hands_door.json", "lamp_hall.json", "mirror_hall.json", "mirror_lamp.json",
          "rotated.json", "scanner_lab.json", "sliding_box.json", "spot_corridor.json", "three_kinds.json",
          "tinted_window.json", "tunnel.json", "vr_study.json", "window_pair.json"}) {
        const layout::Layout l = testing::example_layout(name);
        auto r = bf_renderer(l);
        ASSERT_TRUE(r) << name;
        long with = 0, without = 0;
        for (int k = 0; k < 4; ++k) {
            render::FrameDesc f;
            f.room = l.start.room;
            f.head.position = l.start.position;
            f.head.yaw_deg = l.start.yaw_deg + 90.0 * k;
            f.head.pitch_deg = -15.0;
            f.eye_width = 160;
            f.eye_height = 90;
            const auto [a, b] = bf_compare(*r->renderer, f, std::string(name) + " yaw +" + std::to_string(90 * k));
            with += a;
            without += b;
        }
        // Mirrors' views too: their boxes are seen by reflected eyes.
        if (std::string(name) != "sliding_box.json") {
            EXPECT_LT(with, without) << name;
        }
    }
}

TEST(BoxFaces, AFaceIsLeftOutOnlyWellBehindItsPlaneForEveryEye) {
    render::LevelView view;
    for (render::EyeView& ev : view.eyes) {
        ev.active = true;
        ev.view_proj = glm::dmat4(1.0);
    }
    // Multisampled, so that only the back-face test applies.
    render::BoxFaceView bf;
    bf.pixels_per_radian[0] = bf.pixels_per_radian[1] = 320.0;
    bf.width = 640;
    bf.height = 360;
    bf.samples = 4;
    const glm::dvec3 lo(0.0), hi(0.1);
    const auto faces = [&](glm::dvec3 left, glm::dvec3 right) {
        view.eyes[0].eye.position = left;
        view.eyes[1].eye.position = right;
        return render::box_front_faces(lo, hi, view, bf);
    };
    // From above, front and to the right: the top, +z and +x faces.
    const unsigned top_front_right = (1u << 3) | (1u << 5) | (1u << 1);
    EXPECT_EQ(faces({1.0, 1.6, 1.0}, {1.064, 1.6, 1.0}), top_front_right);
    // Both eyes in the plane of the +x face: it is kept (the rasteriser
    // culls it), the -x face behind them is not.
    EXPECT_EQ(faces({0.1, 1.6, 1.0}, {0.1, 1.6, 1.0}), top_front_right);
    // Eyes either side of the box's x: both x faces.
    EXPECT_EQ(faces({-0.5, 1.6, 1.0}, {0.6, 1.6, 1.0}), top_front_right | (1u << 0));
    // A millimetre behind the +x plane, 1.8 m away: its image would be a
    // sliver, so it is kept; a decimetre behind, it is not.
    EXPECT_NE(faces({0.099, 1.6, 1.0}, {0.099, 1.6, 1.0}) & (1u << 1), 0u);
    EXPECT_EQ(faces({0.0, 1.6, 1.0}, {0.0, 1.6, 1.0}) & (1u << 1), 0u);
    // An inactive eye does not count; none active: every face.
    view.eyes[1].active = false;
    EXPECT_EQ(faces({1.0, 1.6, 1.0}, {-1.0, -1.6, -1.0}), top_front_right);
    view.eyes[0].active = false;
    EXPECT_EQ(faces({1.0, 1.6, 1.0}, {1.0, 1.6, 1.0}), render::kAllBoxFaces);
}

TEST(BoxFaces, AFarBoxBetweenPixelCentresDrawsNoFaceWithOneSampleOnly) {
    // One eye looking down -z from the origin, 90 degrees across 64 x 64
    // pixels: pixel centres at x_ndc = (2 i + 1) / 64 - 1, i.e. odd 32nds.
    render::LevelView view;
    view.eyes[0].active = true;
    view.eyes[0].eye.position = glm::dvec3(0.0);
    view.eyes[0].view_proj = glm::perspective(glm::radians(90.0), 1.0, 0.01, 100.0);
    view.eyes[1].active = false;
    render::BoxFaceView bf = render::box_face_view(view, 64, 64, 1);
    EXPECT_NEAR(bf.pixels_per_radian[0], 32.0, 1e-9);
    // A 1 cm box 10 m away, centred on x_ndc = y_ndc = 0 (a pixel corner):
    // 0.03 pixels across, no centre.
    const glm::dvec3 lo(-0.005, -0.005, -10.005), hi(0.005, 0.005, -9.995);
    EXPECT_EQ(render::box_front_faces(lo, hi, view, bf), 0u);
    // Moved onto a pixel centre: its front (+z) face covers it.
    const glm::dvec3 on(10.0 / 64.0, 10.0 / 64.0, 0.0);
    EXPECT_NE(render::box_front_faces(lo + on, hi + on, view, bf) & (1u << 5), 0u);
    // Multisampled, samples lie anywhere: the faces that face the eye stay.
    bf.samples = 4;
    EXPECT_NE(render::box_front_faces(lo, hi, view, bf) & (1u << 5), 0u);
    // Outside the eye's reach: nothing, however big it looks there.
    bf.samples = 1;
    bf.reach[0] = render::NdcRect{0.5, 0.5, 1.0, 1.0};
    EXPECT_EQ(render::box_front_faces(lo + on, hi + on, view, bf), 0u);
}

TEST(BoxFaces, TheFacesIndicesAreTheBoxPropsOwn) {
    const layout::Layout l = testing::crowded_vr_study(4);
    const scene::Scene s = scene::build_scene(l);
    int boxes = 0;
    for (const scene::CellObjects& cell : s.objects) {
        for (const scene::CellObject& o : cell.objects) {
            ASSERT_GE(o.box_vertex, 0);
            std::vector<std::uint32_t> mine;
            render::append_box_faces(static_cast<std::uint32_t>(o.box_vertex), render::kAllBoxFaces, mine);
            const scene::DrawBatch& b = cell.batches[o.first_batch];
            ASSERT_EQ(o.batch_count, 1u);
            ASSERT_EQ(b.range.count, 36u);
            const std::vector<std::uint32_t> own(s.indices.begin() + b.range.first,
                                                 s.indices.begin() + b.range.first + 36);
            EXPECT_EQ(mine, own);
            ++boxes;
        }
    }
    EXPECT_EQ(boxes, 4 * static_cast<int>(l.rooms.size()));
}

}  // namespace
}  // namespace impossible
