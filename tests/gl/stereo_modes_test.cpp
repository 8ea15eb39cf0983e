// Single-pass instanced stereo against a two-pass render of the same frame,
// and the two headless backends against each other.
#include "gl_fixture.hpp"

namespace impossible {
namespace {

render::FrameDesc frame_of(const layout::Layout& l, render::StereoMode mode) {
    render::FrameDesc f;
    f.head.position = l.start.position;
    f.head.yaw_deg = l.start.yaw_deg;
    f.head.pitch_deg = -8.0;
    f.head.roll_deg = 3.0;
    f.room = l.start.room;
    f.eye_width = 320;
    f.eye_height = 180;
    f.stereo = mode;
    return f;
}

layout::Layout default_layout() {
    return testing::layout_from_file(std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/default.json");
}

TEST(StereoModes, ClipShiftEqualsTwoPass) {
    const layout::Layout l = default_layout();
    const image::Image two = testing::render_once(gl::Backend::Egl, l, frame_of(l, render::StereoMode::TwoPass));
    render::FrameStats stats;
    const image::Image one =
        testing::render_once(gl::Backend::Egl, l, frame_of(l, render::StereoMode::ClipShift), &stats);
    EXPECT_EQ(testing::count_id_differences(one, two), 0);
    EXPECT_EQ(testing::count_colour_differences(one, two, 1), 0);
    EXPECT_GT(stats.draw_calls, 0);
}

TEST(StereoModes, ViewportIndexEqualsTwoPass) {
    const layout::Layout l = default_layout();
    const image::Image two = testing::render_once(gl::Backend::Egl, l, frame_of(l, render::StereoMode::TwoPass));
    const image::Image one = testing::render_once(gl::Backend::Egl, l, frame_of(l, render::StereoMode::ViewportIndex));
    EXPECT_EQ(testing::count_id_differences(one, two), 0);
    EXPECT_EQ(testing::count_colour_differences(one, two, 0), 0);
}

TEST(StereoModes, SinglePassHalvesTheDrawCalls) {
    const layout::Layout l = default_layout();
    render::FrameStats one, two;
    testing::render_once(gl::Backend::Egl, l, frame_of(l, render::StereoMode::ClipShift), &one);
    testing::render_once(gl::Backend::Egl, l, frame_of(l, render::StereoMode::TwoPass), &two);
    EXPECT_EQ(2 * one.draw_calls, two.draw_calls);
    EXPECT_EQ(one.triangles, two.triangles);
}

TEST(Backends, EglAndOSMesaGiveTheSameImage) {
    const layout::Layout l = default_layout();
    const image::Image egl = testing::render_once(gl::Backend::Egl, l, frame_of(l, render::StereoMode::ClipShift));
    const image::Image osmesa =
        testing::render_once(gl::Backend::OSMesa, l, frame_of(l, render::StereoMode::ClipShift));
    ASSERT_FALSE(egl.rgb.empty());
    EXPECT_EQ(egl.rgb, osmesa.rgb);
    EXPECT_EQ(egl.ids, osmesa.ids);
}

}  // namespace
}  // namespace impossible
