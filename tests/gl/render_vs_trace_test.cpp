// The rasteriser against the double-precision reference tracer: for every
// layout in layouts/ and several poses (start views, crossed eyes, an eye
// within the near distance, grazing views, rolled heads), the cell-id maps
// agree to within 0.01% beyond the one-pixel edge tolerance. Prints the
// figures.
#include <cstdio>

#include "app/view_options.hpp"
#include "gl_fixture.hpp"
#include "image/compare.hpp"
#include "trace/tracer.hpp"

namespace impossible {
namespace {

struct PoseCase {
    const char* layout;
    const char* room;
    math::dvec3 position;
    double yaw, pitch, roll;
    const char* what;
};

const PoseCase kCases[] = {
    {"default.json", "hall", {0.3, 1.6, 1.6}, 8, 0, 0, "start"},
    {"default.json", "hall", {0.0, 1.6, 0.005}, 0, 0, 0, "5 mm in front of the door"},
    {"default.json", "hall", {0.1, 1.6, 0.002}, 90, 0, 0, "right eye inside the box"},
    {"default.json", "hall", {0.0, 1.6, -0.01}, 180, -10, 0, "looking back out of the box"},
    {"default.json", "annex", {0.0, 1.6, -0.002}, -90, 0, 0, "crossed eye, other direction"},
    {"default.json", "hall", {1.4, 1.2, 0.3}, 89.9, 0, 0, "grazing the door plane"},
    {"default.json", "hall", {-0.8, 2.0, 1.2}, -30, -25, 20, "rolled and pitched"},
    {"four_rooms.json", "hall", {0.0, 1.6, 1.5}, 0, 0, 0, "start"},
    {"four_rooms.json", "library", {0.2, 1.6, -1.2}, 160, 0, 0, "library to studio"},
    {"tunnel.json", "yard", {0.6, 1.6, 2.6}, 8, 0, 0, "start"},
    {"tunnel.json", "tunnel", {0.1, 1.53, -6.0}, 0, 0, 0, "out of the far end"},
    {"rotated.json", "hall", {0.2, 1.6, 1.6}, 5, 0, 0, "start"},
    {"rotated.json", "gallery", {1.2, 1.5, 0.3}, 80, 0, -10, "back through the turned door"},
    {"corridor.json", "corridor", {0.25, 1.6, 2.0}, 4, 0, 0, "start, deep recursion"},
    {"corridor.json", "corridor", {0.0, 1.2, 3.5}, 0, 0, 0, "straight down the corridor"},
    {"loop.json", "red", {0.0, 1.6, -0.8}, 0, 0, 0, "start"},
    {"loop.json", "red", {0.3, 1.6, -4.5}, -70, 0, 0, "through the side door"},
};

class RenderVsTrace : public ::testing::TestWithParam<render::ClipMode> {};

TEST_P(RenderVsTrace, IdsAgreeOnEveryLayoutAndPose) {
    double worst = 0.0;
    for (const PoseCase& c : kCases) {
        const layout::Layout l =
            testing::layout_from_file(std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/" + c.layout);
        render::FrameDesc f;
        f.head = {c.position, c.yaw, c.pitch, c.roll};
        f.room = layout::find_room(l, c.room);
        f.eye_width = 200;
        f.eye_height = 120;
        f.clip = GetParam();
        const image::Image raster = testing::render_once(gl::Backend::Egl, l, f);

        const image::Image traced = trace::trace_frame(l, app::trace_desc_for(f));

        const image::Image a{raster.width, raster.height, raster.rgb, raster.ids};
        const image::Image b{traced.width, traced.height, traced.rgb, traced.ids};
        ASSERT_FALSE(image::incomparable(a, b)) << c.layout;
        const image::Comparison cmp = image::compare_pictures(a, b);
        std::printf("  %-16s %-32s %s\n", c.layout, c.what, image::summary_line(cmp).c_str());
        EXPECT_LE(cmp.id_mismatch_percent, 0.01) << c.layout << ": " << c.what;
        EXPECT_GE(cmp.interior_psnr_db, 40.0) << c.layout << ": " << c.what;
        worst = std::max(worst, cmp.id_mismatch_percent);
    }
    std::printf("  worst id mismatch: %.4f%%\n", worst);
}

INSTANTIATE_TEST_SUITE_P(ClipModes, RenderVsTrace,
                         ::testing::Values(render::ClipMode::ClipDistance, render::ClipMode::Oblique),
                         [](const auto& info) {
                             return std::string(info.param == render::ClipMode::Oblique ? "oblique" : "clip_distance");
                         });

}  // namespace
}  // namespace impossible
