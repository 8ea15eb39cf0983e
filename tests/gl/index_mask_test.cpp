// The Valve Index's own OpenXR visibility mask (profiles/valve-index.json,
// its line loop, 2 corners per eye above the image; valve-index-mesh.json,
// its visible triangles; docs/headsets.md, "Visibility masks"): the
// rasteriser against the tracer, pixel for pixel, with every hidden pixel
// black and id 0 in both, and about the published hidden share (24.88 %).
#include <cstdio>

#include "cli/view_options.hpp"
#include "gl_fixture.hpp"
#include "image/compare.hpp"
#include "layout/hmd_profile.hpp"
#include "math/hidden_area.hpp"
#include "trace/tracer.hpp"

namespace impossible {
namespace {

class IndexMaskVsTrace : public ::testing::TestWithParam<const char*> {};

TEST_P(IndexMaskVsTrace, IdsAgreeAndTheHiddenAreaIsBlackWithIdZero) {
    const layout::HmdProfile profile =
        layout::read_hmd_profile_file(std::string(IMPOSSIBLE_SOURCE_DIR) + "/profiles/" + GetParam()).value();
    const layout::Layout l = testing::example_layout("default.json");
    render::FrameDesc f;
    f.head.position = l.start.position;
    f.head.yaw_deg = l.start.yaw_deg;
    f.room = l.start.room;
    f.eye_width = 288;  // the panel's 1440x1600 / 5
    f.eye_height = 320;
    f.ipd = profile.ipd;
    f.eye_optics = profile.eyes;
    for (double pitch : {0.0, -12.0}) {
        f.head.pitch_deg = pitch;
        f.head.roll_deg = pitch == 0.0 ? 0.0 : 4.0;
        const image::Image raster = testing::render_once(gl::Backend::Egl, l, f);
        const image::Image traced = trace::trace_frame(l, cli::trace_desc_for(f)).value();
        ASSERT_FALSE(image::incomparable(raster, traced));
        const image::Comparison cmp = image::compare_pictures(raster, traced);
        long hidden = 0;
        for (int e = 0; e < 2; ++e) {
            const std::vector<std::uint8_t> h =
                math::hidden_pixels(profile.eyes[static_cast<size_t>(e)].visible_area, f.eye_width, f.eye_height);
            for (int j = 0; j < f.eye_height; ++j)
                for (int i = 0; i < f.eye_width; ++i) {
                    if (!h[static_cast<size_t>(j * f.eye_width + i)]) continue;
                    ++hidden;
                    const size_t p = static_cast<size_t>(j * 2 * f.eye_width + e * f.eye_width + i);
                    for (const image::Image* im : {&raster, &traced}) {
                        ASSERT_EQ(im->ids[p], 0) << p;
                        ASSERT_EQ(im->rgb[3 * p] | im->rgb[3 * p + 1] | im->rgb[3 * p + 2], 0) << p;
                    }
                }
        }
        const double share = static_cast<double>(hidden) / (2.0 * f.eye_width * f.eye_height);
        std::printf("  %s pitch %.0f: hidden %.2f %%, %s\n", GetParam(), pitch, 100.0 * share,
                    image::summary_line(cmp).c_str());
        EXPECT_EQ(cmp.id_mismatches, 0) << pitch;
        EXPECT_GE(cmp.interior_psnr_db, 40.0) << pitch;
        EXPECT_NEAR(share, 0.2488, 0.005);
    }
}

INSTANTIATE_TEST_SUITE_P(Profiles, IndexMaskVsTrace, ::testing::Values("valve-index.json", "valve-index-mesh.json"),
                         [](const auto& info) {
                             return std::string(info.param) == "valve-index.json" ? "line_loop" : "triangles";
                         });

}  // namespace
}  // namespace impossible
