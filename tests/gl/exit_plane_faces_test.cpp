// A prop face lying in the plane of the door a virtual eye came out of
// (layout-format.md, "What a pixel shows": only what lies strictly in front
// of that plane counts): a box standing on a floor, seen from the room below
// through a trapdoor under it. The tracer clips its bottom face; the
// rasteriser's clip distance there is 0 give or take float rounding, so it
// drew the face (dark, facing down) where the room's ceiling shows
// (render/objects/box_faces.hpp, faces_in_clip_planes, leaves such faces out).
#include "cli/view_options.hpp"
#include "gl_fixture.hpp"
#include "image/compare.hpp"
#include "trace/tracer.hpp"

namespace impossible {
namespace {

constexpr const char* kTrapdoorUnderABox = R"({"format": "impossible-layout", "version": 1,
  "start": {"room": "cellar", "position": [0.1, -1.5, 0.4]},
  "rooms": [
    {"id": "loft", "floor": [[-2, -2], [2, -2], [2.5, 0], [2, 2], [-2, 2]], "y": [0, 3],
     "color": [0.9, 0.9, 0.85],
     "props": [{"box": {"min": [-0.3, 0, -0.6], "max": [0.4, 1.2, 0.1]}, "color": [0.9, 0.1, 0.1]}]},
    {"id": "cellar", "min": [-2, -3, -2], "max": [2, 0, 2], "color": [0.3, 0.4, 0.6]}],
  "portals": [
    {"id": "down", "room": "loft", "center": [0, 0, 0], "normal": [0, 1, 0], "up": [0, 0, -1],
     "width": 1.2, "height": 1.2, "target": "up"},
    {"id": "up", "room": "cellar", "center": [0, 0, 0], "normal": [0, -1, 0], "up": [0, 0, -1],
     "width": 1.2, "height": 1.2, "target": "down"}]})";

class ExitPlaneFaces : public ::testing::TestWithParam<render::ClipMode> {};

TEST_P(ExitPlaneFaces, ABoxOnAFloorSeenFromBelowThroughATrapdoorShowsNoBottomFace) {
    const layout::Layout l = testing::layout_from_text(kTrapdoorUnderABox);
    for (const double pitch : {80.0, 60.0}) {
        render::FrameDesc f;
        f.head = {{0.1, -1.5, 0.6}, 0.0, pitch, 0.0};
        f.room = layout::find_room(l, "cellar");
        f.eye_width = 160;
        f.eye_height = 120;
        f.clip = GetParam();
        const image::Image raster = testing::render_once(gl::Backend::Egl, l, f);
        const image::Image traced = trace::trace_frame(l, cli::trace_desc_for(f)).value();
        const image::Comparison cmp = image::compare_pictures(raster, traced);
        EXPECT_EQ(cmp.id_mismatches, 0) << pitch;
        // The box's bottom face, drawn, differs from the loft's ceiling by
        // far more than rounding: without faces_in_clip_planes about 24 dB here.
        EXPECT_GE(cmp.interior_psnr_db, 40.0) << pitch << ": " << image::summary_line(cmp);
    }
}

INSTANTIATE_TEST_SUITE_P(ClipModes, ExitPlaneFaces,
                         ::testing::Values(render::ClipMode::ClipDistance, render::ClipMode::Oblique),
                         [](const auto& info) {
                             return std::string(info.param == render::ClipMode::Oblique ? "oblique" : "clip_distance");
                         });

}  // namespace
}  // namespace impossible
