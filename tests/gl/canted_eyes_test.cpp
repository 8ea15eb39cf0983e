// Per-eye poses (View::eye_offsets, docs/headsets.md): the rasteriser
// against the tracer with canted eyes (each turned 5° outwards, as the Valve
// Index's), in both clip modes and all three stereo modes, on the default
// layout, through a headset's angles and hidden area, and with the door's
// plane running between the eyes (one eye inside the door's box, reached
// from the head through the door; the other in front of it).
#include <algorithm>
#include <cstdio>

#include "cli/view_options.hpp"
#include "gl_fixture.hpp"
#include "image/compare.hpp"
#include "layout/hmd_profile.hpp"
#include "math/eyes.hpp"
#include "technique_modes.hpp"
#include "trace/tracer.hpp"

namespace impossible::canted_eyes {
namespace {

constexpr int kHall = 1, kAnnex = 2;  // ids: 1 + room index

// Eyes at ±ipd/2 (the left one `ahead` metres in front of the head centre),
// each turned `cant` degrees outwards about the head's vertical axis.
std::array<math::EyeOffset, 2> canted(double ipd, double cant, double ahead = 0.0) {
    return {math::eye_offset(math::HeadPose{{-0.5 * ipd, 0.0, -ahead}, cant, 0.0, 0.0}),
            math::eye_offset(math::HeadPose{{0.5 * ipd, 0.0, 0.0}, -cant, 0.0, 0.0})};
}

render::FrameDesc start_frame(const layout::Layout& l) {
    render::FrameDesc f;
    f.head.position = l.start.position;
    f.head.yaw_deg = l.start.yaw_deg;
    f.room = l.start.room;
    f.eye_width = 240;
    f.eye_height = 200;
    f.eye_offsets = canted(0.0635, 5.0);
    return f;
}

image::Comparison compared(const layout::Layout& l, const render::FrameDesc& f, const char* what,
                           image::Image* raster_out = nullptr) {
    const image::Image raster = testing::render_once(gl::Backend::Egl, l, f);
    const image::Image traced = trace::trace_frame(l, cli::trace_desc_for(f)).value();
    EXPECT_FALSE(image::incomparable(raster, traced));
    const image::Comparison cmp = image::compare_pictures(raster, traced);
    std::printf("  %s: %s\n", what, image::summary_line(cmp).c_str());
    if (raster_out) *raster_out = raster;
    return cmp;
}

// How many pixels of eye `eye` show cell id `id`.
long eye_count(const image::Image& im, int eye, int id) {
    long n = 0;
    const int w = im.width / 2;
    for (int j = 0; j < im.height; ++j)
        for (int i = eye * w; i < (eye + 1) * w; ++i) n += im.ids[static_cast<size_t>(j * im.width + i)] == id;
    return n;
}

using Modes = std::tuple<render::ClipMode, render::StereoMode>;
class CantedVsTrace : public ::testing::TestWithParam<Modes> {
protected:
    render::FrameDesc frame(const layout::Layout& l) const {
        render::FrameDesc f = start_frame(l);
        f.clip = std::get<0>(GetParam());
        f.stereo = std::get<1>(GetParam());
        return f;
    }
};

TEST_P(CantedVsTrace, TheDefaultLayoutAgrees) {
    const layout::Layout l = testing::example_layout("default.json");
    render::FrameDesc f = frame(l);
    EXPECT_EQ(compared(l, f, "level").id_mismatches, 0);
    f.head.pitch_deg = -12.0;
    f.head.roll_deg = 4.0;
    EXPECT_EQ(compared(l, f, "pitched and rolled").id_mismatches, 0);
    // Through a headset's angles and hidden area: the mask is in each eye's
    // image, so it turns with the eye.
    const layout::HmdProfile vive =
        layout::read_hmd_profile_file(std::string(IMPOSSIBLE_SOURCE_DIR) + "/profiles/htc-vive.json").value();
    f.eye_optics = vive.eyes;
    EXPECT_EQ(compared(l, f, "vive optics").id_mismatches, 0);
}

TEST_P(CantedVsTrace, TheDoorPlaneBetweenTheEyes) {
    // The head 2 cm in front of the door's plane (z = 0) near its right
    // edge (x = 0.5), facing it; the left eye 6 cm ahead of the head stands
    // 4 cm past the plane, inside the door's box, and sees the annex only
    // (through the box's inner faces); the right eye, in front, sees the
    // door's edge with the hall beside it.
    const layout::Layout l = testing::example_layout("default.json");
    render::FrameDesc f = frame(l);
    f.head = math::HeadPose{{0.45, 1.6, 0.02}, 0.0, 0.0, 0.0};
    f.room = layout::find_room(l, "hall");
    f.eye_offsets = canted(0.0635, 5.0, 0.06);
    image::Image raster;
    EXPECT_EQ(compared(l, f, "straddling", &raster).id_mismatches, 0);
    const long eye_pixels = static_cast<long>(f.eye_width) * f.eye_height;
    EXPECT_EQ(eye_count(raster, 0, kAnnex), eye_pixels);
    EXPECT_GT(eye_count(raster, 1, kHall), 0);
    EXPECT_GT(eye_count(raster, 1, kAnnex), 0);
    // Turned and pitched, so that the left eye sees the box's inner faces.
    f.head.yaw_deg = 35.0;
    f.head.pitch_deg = -20.0;
    EXPECT_EQ(compared(l, f, "straddling, turned").id_mismatches, 0);
}

INSTANTIATE_TEST_SUITE_P(Modes, CantedVsTrace, testing::all_technique_modes(), testing::technique_modes_name);

}  // namespace
}  // namespace impossible::canted_eyes
