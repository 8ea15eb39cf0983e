// Mirrors and windows, the rasteriser against the tracer (issue "mirrors and
// windows"): the three kinds' layouts, over poses with an eye 1 mm from a
// mirror and from a window, grazing views, mirrors seen through a door and
// doors seen in mirrors, nested windows; at depth 1, 8 and 64, in both clip
// modes. Ids agree exactly (one-pixel edge tolerance) and colour to 40 dB.
#include <cstdio>

#include "cli/view_options.hpp"
#include "gl_fixture.hpp"
#include "image/compare.hpp"
#include "trace/tracer.hpp"

namespace impossible {
namespace {

struct GlassPose {
    const char* layout;
    const char* room;
    math::dvec3 position;
    double yaw, pitch;
    const char* what;
};

const GlassPose kGlassPoses[] = {
    {"mirror_hall.json", "hall", {0.6, 1.6, 2.4}, 35, 0, "start: the door in both mirrors"},
    {"mirror_hall.json", "hall", {-3 + 0.001, 1.6, 0.5}, 90, 0, "both eyes 1 mm from a mirror"},
    {"mirror_hall.json", "hall", {2.2, 1.5, -0.5}, -60, -10, "the row of reflections"},
    {"mirror_hall.json", "hall", {-2.95, 1.6, 3.6}, 1, 0, "grazing the west mirror"},
    {"mirror_hall.json", "garden", {0.3, 1.6, 3.5}, 180, 0, "the mirrors through the garden's door"},
    {"glass_gallery.json", "gallery", {-0.8, 1.6, 1.8}, -20, 0, "start: both windows"},
    {"glass_gallery.json", "gallery", {2.8, 1.5, -2.9}, 90, 0, "grazing the north window"},
    {"glass_gallery.json", "gallery", {3 - 0.001, 1.4, 0.2}, -90, 0, "both eyes 1 mm from a window"},
    {"glass_gallery.json", "gallery", {-2.5, 1.2, 2.5}, -45, 5, "the east window at an angle"},
    {"window_pair.json", "studio", {0.9, 1.6, 1.2}, 62, 0, "an angled view of the nested windows"},
    {"window_pair.json", "studio", {0.0, 1.4, 0.0}, 90, 0, "straight down the nested windows"},
    {"three_kinds.json", "atelier", {0.0, 1.6, 2.2}, 0, 0, "a door, a mirror, a window from afar"},
    {"three_kinds.json", "atelier", {-1.2, 1.3, -1.0}, 30, -20, "close to the mirror and the door"},
};

layout::Layout glass_layout(const char* file) {
    return testing::layout_from_file(std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/" + file);
}

// The layout's start view, width × height per eye.
render::FrameDesc start_frame(const layout::Layout& l, int width, int height) {
    render::FrameDesc f;
    f.head.position = l.start.position;
    f.head.yaw_deg = l.start.yaw_deg;
    f.room = l.start.room;
    f.eye_width = width;
    f.eye_height = height;
    return f;
}

struct GlassCase {
    render::ClipMode clip;
    int depth;
};

class GlassRender : public ::testing::TestWithParam<GlassCase> {};

TEST_P(GlassRender, IdsAndColoursAgreeWithTheTracer) {
    for (const GlassPose& c : kGlassPoses) {
        const layout::Layout l = glass_layout(c.layout);
        render::FrameDesc f;
        f.head = {c.position, c.yaw, c.pitch, 0.0};
        f.room = layout::find_room(l, c.room);
        f.eye_width = 128;
        f.eye_height = 80;
        f.max_depth = GetParam().depth;
        f.clip = GetParam().clip;
        render::FrameStats stats;
        const image::Image raster = testing::render_once(gl::Backend::Egl, l, f, &stats);
        const image::Image traced = trace::trace_frame(l, cli::trace_desc_for(f)).value();
        ASSERT_FALSE(image::incomparable(raster, traced)) << c.layout;
        const image::Comparison cmp = image::compare_pictures(raster, traced);
        std::printf("  %-18s %-40s passes=%d %s\n", c.layout, c.what, stats.portal_passes_drawn,
                    image::summary_line(cmp).c_str());
        EXPECT_EQ(cmp.id_mismatches, 0) << c.layout << ": " << c.what;
        EXPECT_GE(cmp.psnr_db, 40.0) << c.layout << ": " << c.what;
    }
}

INSTANTIATE_TEST_SUITE_P(
    DepthsAndClipModes, GlassRender,
    ::testing::Values(GlassCase{render::ClipMode::ClipDistance, 1}, GlassCase{render::ClipMode::ClipDistance, 8},
                      GlassCase{render::ClipMode::ClipDistance, 64}, GlassCase{render::ClipMode::Oblique, 1},
                      GlassCase{render::ClipMode::Oblique, 8}, GlassCase{render::ClipMode::Oblique, 64}),
    [](const auto& info) {
        return std::string(info.param.clip == render::ClipMode::Oblique ? "oblique" : "clip_distance") + "_depth" +
               std::to_string(info.param.depth);
    });

// Multisampled (4 samples, llvmpipe's one count), the window's copy is a
// multisample texture read per sample; with render-to-texture portals,
// mirrors and windows keep the stencil path. With portal textures, ids
// agree exactly and colours to 40 dB. Multisampled, colours agree to 35 dB
// against the 4-sample trace (shading runs once per pixel, so checker edges
// inside a surface stay aliased: 36-37 dB here, as for doors in checker-rich
// views); a pixel's id is its samples' majority and the tracer's its centre
// ray's, which differ where a feature is smaller than a pixel: the windows
// nested to sub-pixel size in window_pair.json, 4 pixels of 20,480.
TEST(GlassRender, MultisampledAndWithPortalTextures) {
    for (const char* file : {"mirror_hall.json", "glass_gallery.json", "window_pair.json", "three_kinds.json"}) {
        const layout::Layout l = glass_layout(file);
        render::FrameDesc f = start_frame(l, 128, 80);
        f.samples = 4;
        const image::Image multi = testing::render_once(gl::Backend::Egl, l, f);
        const image::Image traced_multi = trace::trace_frame(l, cli::trace_desc_for(f)).value();
        const image::Comparison m = image::compare_pictures(multi, traced_multi);
        std::printf("  %-18s 4 samples      %s\n", file, image::summary_line(m).c_str());
        EXPECT_LE(m.id_mismatch_percent, 0.05) << file;
        EXPECT_GE(m.psnr_db, 35.0) << file;

        f.samples = 1;
        f.portal_texture_scale = 1.0;
        const image::Image textured = testing::render_once(gl::Backend::Egl, l, f);
        const image::Image traced = trace::trace_frame(l, cli::trace_desc_for(f)).value();
        const image::Comparison t = image::compare_pictures(textured, traced);
        std::printf("  %-18s portal textures %s\n", file, image::summary_line(t).c_str());
        EXPECT_EQ(t.id_mismatches, 0) << file;
        EXPECT_GE(t.psnr_db, 40.0) << file;
    }
}

// The stereo modes, culling off and the occlusion test change the work, never
// the image, with mirrors and windows in view as with doors: ids agree,
// colours within one step (the two-pass and viewport-index draws round a
// tint or a blend differently here and there).
TEST(GlassRender, StereoModesCullingAndOcclusionDrawTheSameImage) {
    for (const char* file : {"mirror_hall.json", "glass_gallery.json", "window_pair.json", "three_kinds.json"}) {
        const layout::Layout l = glass_layout(file);
        const render::FrameDesc base = start_frame(l, 128, 80);
        const image::Image reference = testing::render_once(gl::Backend::Egl, l, base);
        std::vector<std::pair<const char*, render::FrameDesc>> variants;
        render::FrameDesc f = base;
        f.stereo = render::StereoMode::TwoPass;
        variants.emplace_back("two-pass", f);
        f.stereo = render::StereoMode::ViewportIndex;
        variants.emplace_back("viewport-index", f);
        f = base;
        f.cull_portals = false;
        variants.emplace_back("no culling", f);
        f = base;
        f.occlusion_test = true;
        variants.emplace_back("occlusion test", f);
        for (const auto& [what, desc] : variants) {
            const image::Image other = testing::render_once(gl::Backend::Egl, l, desc);
            const image::Comparison c = image::compare_pictures(reference, other);
            EXPECT_EQ(c.id_mismatches, 0) << file << ", " << what;
            EXPECT_LE(c.max_error, 1) << file << ", " << what;
        }
    }
}

// Single-pass stereo draws each mesh once for both eyes; two-pass draws it
// once per eye. With mirrors and windows in view the count still halves
// (the full-target triangles of the tint and blend steps included). With
// every door pass: the cheaper steps (PortalSteps) depend on how near the
// portals come in both eyes at once or in one, which differs between the two.
TEST(GlassRender, SinglePassHalvesTheDrawCalls) {
    for (const char* file : {"mirror_hall.json", "glass_gallery.json", "three_kinds.json"}) {
        const layout::Layout l = glass_layout(file);
        render::FrameDesc f = start_frame(l, 96, 64);
        f.portal_steps = false;
        render::FrameStats single, two;
        testing::render_once(gl::Backend::Egl, l, f, &single);
        f.stereo = render::StereoMode::TwoPass;
        testing::render_once(gl::Backend::Egl, l, f, &two);
        std::printf("  %-18s draw calls: single pass %ld, two passes %ld\n", file, single.draw_calls, two.draw_calls);
        EXPECT_GT(single.portal_passes_drawn, 1) << file;
        EXPECT_LE(2 * single.draw_calls, two.draw_calls + 2) << file;
    }
}

}  // namespace
}  // namespace impossible
