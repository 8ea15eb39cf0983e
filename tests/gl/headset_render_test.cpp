// Headset optics (docs/headsets.md): the rasteriser against the tracer with
// each eye's asymmetric frustum and hidden area, in both clip modes and all
// three stereo modes; the mask leaves the visible area byte for byte as
// the same frusta draw it unmasked, writes black and id 0 elsewhere, saves
// at least one colour fragment per hidden pixel, and culls a portal that
// only the hidden area holds.
#include <cstdio>

#include "cli/view_options.hpp"
#include "gl_fixture.hpp"
#include "image/compare.hpp"
#include "layout/hmd_profile.hpp"
#include "math/hidden_area.hpp"
#include "technique_modes.hpp"
#include "trace/tracer.hpp"

namespace impossible {
namespace {

layout::HmdProfile vive() {
    return layout::read_hmd_profile_file(std::string(IMPOSSIBLE_SOURCE_DIR) + "/profiles/htc-vive.json").value();
}

// The default layout's start view (the door ahead) through the profile, at
// 321x340 per eye.
render::FrameDesc headset_frame(const layout::Layout& l, const layout::HmdProfile& profile) {
    render::FrameDesc f;
    f.head.position = l.start.position;
    f.head.yaw_deg = l.start.yaw_deg;
    f.room = l.start.room;
    f.eye_width = 321;
    f.eye_height = 340;
    f.ipd = profile.ipd;
    f.eye_optics = profile.eyes;
    return f;
}

layout::Layout default_layout() { return testing::example_layout("default.json"); }

// Each eye's hidden pixels, side by side as the frame's image holds them.
std::vector<std::uint8_t> hidden_of(const render::FrameDesc& f) {
    std::vector<std::uint8_t> out(static_cast<size_t>(2 * f.eye_width * f.eye_height), 0);
    for (int e = 0; e < 2; ++e) {
        const std::vector<std::uint8_t> h =
            math::hidden_pixels((*f.eye_optics)[static_cast<size_t>(e)].visible_area, f.eye_width, f.eye_height);
        for (int j = 0; j < f.eye_height; ++j)
            for (int i = 0; i < f.eye_width; ++i)
                out[static_cast<size_t>(j * 2 * f.eye_width + e * f.eye_width + i)] =
                    h[static_cast<size_t>(j * f.eye_width + i)];
    }
    return out;
}

using Modes = std::tuple<render::ClipMode, render::StereoMode>;
class HeadsetVsTrace : public ::testing::TestWithParam<Modes> {};

TEST_P(HeadsetVsTrace, IdsAgreeAndTheHiddenAreaIsBlackWithIdZero) {
    const layout::Layout l = default_layout();
    render::FrameDesc f = headset_frame(l, vive());
    f.clip = std::get<0>(GetParam());
    f.stereo = std::get<1>(GetParam());
    for (double pitch : {0.0, -12.0}) {
        f.head.pitch_deg = pitch;
        f.head.roll_deg = pitch == 0.0 ? 0.0 : 4.0;
        const image::Image raster = testing::render_once(gl::Backend::Egl, l, f);
        const image::Image traced = trace::trace_frame(l, cli::trace_desc_for(f)).value();
        ASSERT_FALSE(image::incomparable(raster, traced));
        const image::Comparison cmp = image::compare_pictures(raster, traced);
        std::printf("  pitch %.0f: %s\n", pitch, image::summary_line(cmp).c_str());
        EXPECT_EQ(cmp.id_mismatches, 0) << pitch;
        EXPECT_GE(cmp.interior_psnr_db, 40.0) << pitch;
        const std::vector<std::uint8_t> hidden = hidden_of(f);
        long hidden_count = 0;
        for (size_t p = 0; p < hidden.size(); ++p) {
            if (!hidden[p]) continue;
            ++hidden_count;
            for (const image::Image* im : {&raster, &traced}) {
                ASSERT_EQ(im->ids[p], 0) << p;
                ASSERT_EQ(im->rgb[3 * p] | im->rgb[3 * p + 1] | im->rgb[3 * p + 2], 0) << p;
            }
        }
        // About 19 % of each eye (profiles/htc-vive.json).
        EXPECT_NEAR(static_cast<double>(hidden_count) / static_cast<double>(hidden.size()), 0.19, 0.01);
    }
}

INSTANTIATE_TEST_SUITE_P(Modes, HeadsetVsTrace, testing::all_technique_modes(), testing::technique_modes_name);

TEST(HeadsetMask, TheVisibleAreaIsByteIdenticalToTheUnmaskedFrame) {
    const layout::Layout l = testing::example_layout("gallery.json");
    render::FrameDesc masked = headset_frame(l, vive());
    masked.profile = true;
    render::FrameDesc open = masked;
    for (math::EyeOptics& e : *open.eye_optics) e.visible_area.clear();
    const std::vector<std::uint8_t> hidden = hidden_of(masked);
    struct Variant {
        render::StereoMode stereo;
        int samples;
    };
    for (const Variant v : {Variant{render::StereoMode::ClipShift, 1}, Variant{render::StereoMode::TwoPass, 1},
                            Variant{render::StereoMode::ClipShift, 4}}) {
        masked.stereo = open.stereo = v.stereo;
        masked.samples = open.samples = v.samples;
        render::FrameStats ms, os;
        const image::Image a = testing::render_once(gl::Backend::Egl, l, masked, &ms);
        const image::Image b = testing::render_once(gl::Backend::Egl, l, open, &os);
        ASSERT_EQ(a.ids.size(), b.ids.size());
        long hidden_count = 0, differing = 0, unmasked = 0;
        for (size_t p = 0; p < hidden.size(); ++p) {
            const bool rgb_equal = a.rgb[3 * p] == b.rgb[3 * p] && a.rgb[3 * p + 1] == b.rgb[3 * p + 1] &&
                                   a.rgb[3 * p + 2] == b.rgb[3 * p + 2];
            if (hidden[p]) {
                ++hidden_count;
                unmasked += a.ids[p] != 0 || (a.rgb[3 * p] | a.rgb[3 * p + 1] | a.rgb[3 * p + 2]) != 0;
                continue;
            }
            // Multisampled, an id at the mask's edge may resolve otherwise: a
            // tie between two ids is broken by the 3 x 3 block around the
            // pixel, which holds hidden pixels (docs/accuracy.md).
            differing += !rgb_equal || (v.samples == 1 && a.ids[p] != b.ids[p]);
        }
        EXPECT_EQ(unmasked, 0) << v.samples;
        EXPECT_EQ(differing, 0) << v.samples;
        // Every pixel of a closed room takes at least one colour fragment
        // (sample) unmasked; masked, the hidden ones take none.
        std::printf("  samples %d: colour fragments masked %ld, unmasked %ld, hidden pixels %ld\n", v.samples,
                    ms.colour_fragments, os.colour_fragments, hidden_count);
        EXPECT_GT(hidden_count, 0);
        EXPECT_LE(ms.colour_fragments, os.colour_fragments - v.samples * hidden_count);
        EXPECT_EQ(ms.portal_passes_drawn, os.portal_passes_drawn);
    }
}

TEST(HeadsetMask, APortalOnlyTheHiddenAreaHoldsIsCulled) {
    const layout::Layout l = default_layout();
    render::FrameDesc f = headset_frame(l, vive());
    render::FrameStats open_stats;
    for (math::EyeOptics& e : *f.eye_optics) e.visible_area.clear();
    testing::render_once(gl::Backend::Egl, l, f, &open_stats);
    ASSERT_GE(open_stats.portal_passes_drawn, 1);
    EXPECT_EQ(open_stats.portal_passes_masked, 0);
    // Only a strip along the left edge is visible: the door ahead is hidden.
    for (math::EyeOptics& e : *f.eye_optics) e.visible_area = {{0, 0}, {0.08, 0}, {0.08, 1}, {0, 1}};
    render::FrameStats stats;
    const image::Image raster = testing::render_once(gl::Backend::Egl, l, f, &stats);
    EXPECT_EQ(stats.portal_passes_drawn, 0);
    EXPECT_EQ(stats.portal_passes_masked, open_stats.portal_passes_drawn);
    EXPECT_GE(stats.portal_passes_culled, stats.portal_passes_masked);
    EXPECT_EQ(stats.max_level_reached, 0);
    const image::Image traced = trace::trace_frame(l, cli::trace_desc_for(f)).value();
    EXPECT_EQ(image::compare_pictures(raster, traced).id_mismatches, 0);
}

}  // namespace
}  // namespace impossible
