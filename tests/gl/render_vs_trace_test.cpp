// The rasteriser against the double-precision reference tracer: for every
// layout in layouts/ and several poses (start views, crossed eyes, an eye
// within the near distance, grazing views, rolled heads), the cell-id maps
// agree to within 0.01% beyond the one-pixel edge tolerance. Prints the
// figures.
#include <cstdio>

#include "cli/view_options.hpp"
#include "gl_fixture.hpp"
#include "image/compare.hpp"
#include "pose_cases.hpp"
#include "trace/tracer.hpp"

namespace impossible {
namespace {

using testing::kPoseCases;
using testing::PoseCase;

class RenderVsTrace : public ::testing::TestWithParam<render::ClipMode> {};

TEST_P(RenderVsTrace, IdsAgreeOnEveryLayoutAndPose) {
    double worst = 0.0;
    for (const PoseCase& c : kPoseCases) {
        const layout::Layout l = testing::layout_from_file(std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/" + c.layout);
        render::FrameDesc f;
        f.head = {c.position, c.yaw, c.pitch, c.roll};
        f.room = layout::find_room(l, c.room);
        f.eye_width = 200;
        f.eye_height = 120;
        f.clip = GetParam();
        const image::Image raster = testing::render_once(gl::Backend::Egl, l, f);

        const image::Image traced = trace::trace_frame(l, cli::trace_desc_for(f)).value();

        ASSERT_FALSE(image::incomparable(raster, traced)) << c.layout;
        const image::Comparison cmp = image::compare_pictures(raster, traced);
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
