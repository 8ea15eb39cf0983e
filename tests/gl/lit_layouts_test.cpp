// The lit example layouts (issue 27: the lamp hall, the mirror lamp, the
// tinted window and the spot corridor; issue 23: the lit L-shaped flat,
// whose walls cast shadows) against the tracer: 0 id mismatches
// and at least 40 dB of colour PSNR over interior pixels, the goal for lit
// layouts whose props cast shadows (shadow maps approximate them). Prints the
// figures.
#include <cstdio>

#include "cli/view_options.hpp"
#include "gl_fixture.hpp"
#include "image/compare.hpp"
#include "trace/tracer.hpp"

namespace impossible {
namespace {

struct LitLayoutCase {
    const char* layout;
    const char* room;
    math::dvec3 position;
    double yaw, pitch;
    const char* what;
};

const LitLayoutCase kLitLayoutCases[] = {
    {"lamp_hall.json", "hall", {-1.6, 1.6, 1.2}, -70, 0, "start"},
    {"lamp_hall.json", "annex", {1.9, 2.0, 0.0}, 90, -35, "the pool of light through the door"},
    {"lamp_hall.json", "hall", {-1.7, 1.6, 0.4}, -80, -15, "the lamp, the table and the door"},
    {"mirror_lamp.json", "salon", {0.4, 1.6, 1.7}, 10, 0, "start: the lamp and its image"},
    {"tinted_window.json", "greenhouse", {5.2, 1.7, 0.4}, 80, -20, "green light through the window"},
    {"tinted_window.json", "workshop", {-1.5, 1.6, 1.5}, -60, -10, "the lamp and the pane's reflection"},
    {"spot_corridor.json", "corridor", {0.0, 1.6, 1.5}, 0, -12, "start: spots and pillars"},
    {"spot_corridor.json", "gallery", {2.7, 1.6, -4.3}, 37, -20, "the gallery lit through the door"},
    {"lit_flat.json", "hall", {1.5, 1.6, -1.6}, 138, -20, "the corner's shadow across the north arm"},
    {"lit_flat.json", "hall", {-1.8, 1.7, 2.2}, -39, -20, "the north arm: shadow and two doors"},
    {"lit_flat.json", "bedroom", {1.5, 1.6, 2.0}, 150, -20, "the hall's lamp through the bedroom door"},
};

TEST(LitLayouts, AgreeWithTheTracer) {
    double worst_psnr = 1e9;
    for (const LitLayoutCase& c : kLitLayoutCases) {
        const layout::Layout l = testing::layout_from_file(std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/" + c.layout);
        ASSERT_EQ(l.lighting, layout::Lighting::Lights) << c.layout;
        render::FrameDesc f;
        f.head = {c.position, c.yaw, c.pitch, 0.0};
        f.room = layout::find_room(l, c.room);
        ASSERT_GE(f.room, 0) << c.layout << ": " << c.room;
        f.eye_width = 200;
        f.eye_height = 120;
        const image::Image raster = testing::render_once(gl::Backend::Egl, l, f);
        const image::Image traced = trace::trace_frame(l, cli::trace_desc_for(f)).value();
        ASSERT_FALSE(image::incomparable(raster, traced)) << c.layout;
        const image::Comparison cmp = image::compare_pictures(raster, traced);
        std::printf("  %-20s %-40s %s\n", c.layout, c.what, image::summary_line(cmp).c_str());
        EXPECT_EQ(cmp.id_mismatches, 0) << c.layout << ": " << c.what;
        EXPECT_GE(cmp.interior_psnr_db, 40.0) << c.layout << ": " << c.what;
        worst_psnr = std::min(worst_psnr, cmp.interior_psnr_db);
    }
    std::printf("  worst interior PSNR: %.2f dB\n", worst_psnr);
}

// The lights change colours, never ids: each lit layout's id map equals the
// same layout's under the fixed light.
TEST(LitLayouts, IdsDoNotDependOnLighting) {
    for (const LitLayoutCase& c : kLitLayoutCases) {
        layout::Layout l = testing::layout_from_file(std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/" + c.layout);
        render::FrameDesc f;
        f.head = {c.position, c.yaw, c.pitch, 0.0};
        f.room = layout::find_room(l, c.room);
        f.eye_width = 120;
        f.eye_height = 72;
        const image::Image lit = testing::render_once(gl::Backend::Egl, l, f);
        l.lighting = layout::Lighting::Fixed;
        const image::Image fixed = testing::render_once(gl::Backend::Egl, l, f);
        EXPECT_EQ(lit.ids, fixed.ids) << c.layout << ": " << c.what;
        EXPECT_NE(lit.rgb, fixed.rgb) << c.layout << ": " << c.what;
    }
}

}  // namespace
}  // namespace impossible
