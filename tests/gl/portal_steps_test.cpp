// Cheaper door passes (render/portals/portal_steps.cpp, PortalSteps): a portal that
// no other of its level comes near on screen is marked with its depth reset
// in one draw (the stencil's box bit), and one that no later portal comes
// near is not unmarked. The image is the one drawn with every step, byte for
// byte, for every kind of portal, and the frame takes fewer draws.
#include <cstdio>

#include "gl_fixture.hpp"
#include "render/portals/passes.hpp"

namespace impossible {
namespace {

struct StepsPose {
    glm::dvec3 offset;
    double yaw;
};

// The start and poses around it, some turned so that doors overlap on screen.
const StepsPose kStepsPoses[] = {{{0, 0, 0}, 0},       {{0.3, 0, 0.4}, 25},   {{-0.4, 0, 0.2}, -30},
                                 {{0.2, 0, -0.3}, 60}, {{-0.2, 0, 0.5}, 150}, {{0, 0, 0.3}, 200}};

struct StepsTotals {
    int frames = 0, drawn = 0, one_draw = 0, skipped = 0;
};

// Renders every pose of `file` with the steps and without, and compares.
void steps_compare(const char* file, render::FrameDesc base, StepsTotals& totals) {
    const layout::Layout l = testing::example_layout(file);
    Result<gl::Context> context = gl::create_context(gl::Backend::Egl);
    ASSERT_TRUE(context.has_value()) << context.error();
    Result<render::Renderer> renderer = render::Renderer::create(context->state(), scene::build_scene(l));
    ASSERT_TRUE(renderer.has_value()) << renderer.error();
    for (const StepsPose& pose : kStepsPoses) {
        render::FrameDesc f = base;
        f.room = l.start.room;
        f.head.position = l.start.position + pose.offset;
        f.head.yaw_deg = l.start.yaw_deg + pose.yaw;
        f.portal_steps = true;
        Result<render::RenderedFrame> cheap = renderer->render(f);
        f.portal_steps = false;
        Result<render::RenderedFrame> every = renderer->render(f);
        ASSERT_TRUE(cheap && every) << file;
        const std::string what = std::string(file) + " yaw " + std::to_string(pose.yaw);
        EXPECT_EQ(testing::count_colour_differences(cheap->image, every->image), 0) << what;
        EXPECT_EQ(testing::count_id_differences(cheap->image, every->image), 0) << what;
        const render::FrameStats& c = cheap->stats;
        EXPECT_EQ(c.portal_passes_drawn, every->stats.portal_passes_drawn) << what;
        EXPECT_EQ(every->stats.one_draw_marks + every->stats.unmarks_skipped, 0) << what;
        // Each step left out is one draw of a box (two with its inner faces)
        // or none: a quad replaced the box's mark.
        EXPECT_GE(every->stats.draw_calls - c.draw_calls, c.one_draw_marks + c.unmarks_skipped) << what;
        totals.frames += 1;
        totals.drawn += c.portal_passes_drawn;
        totals.one_draw += c.one_draw_marks;
        totals.skipped += c.unmarks_skipped;
    }
}

render::FrameDesc steps_frame(int width, int height) {
    render::FrameDesc f;
    f.eye_width = width;
    f.eye_height = height;
    return f;
}

TEST(PortalSteps, SixDoorsTakeOneDrawToMarkAndNoUnmark) {
    const layout::Layout l = testing::example_layout("vr_study.json");
    render::FrameDesc f = steps_frame(320, 180);
    f.room = l.start.room;
    f.head.position = l.start.position;
    f.head.yaw_deg = l.start.yaw_deg;
    render::FrameStats cheap, every;
    const image::Image a = testing::render_once(gl::Backend::Egl, l, f, &cheap);
    f.portal_steps = false;
    const image::Image b = testing::render_once(gl::Backend::Egl, l, f, &every);
    EXPECT_EQ(testing::count_colour_differences(a, b), 0);
    EXPECT_EQ(testing::count_id_differences(a, b), 0);
    // The six doors stand apart on screen: each is marked by its quads and
    // never unmarked, two draws fewer each.
    EXPECT_EQ(cheap.portal_passes_drawn, 6);
    EXPECT_EQ(cheap.one_draw_marks, 6);
    EXPECT_EQ(cheap.unmarks_skipped, 6);
    EXPECT_EQ(every.draw_calls - cheap.draw_calls, 12);
}

// Doors, mirrors, windows, volumes, crossing objects: the same image with
// and without the steps at every pose, and both kinds of step taken and
// declined somewhere (overlapping portals fall back to the box's mark and
// the unmark).
TEST(PortalSteps, EveryKindOfPortalDrawsTheSameImage) {
    StepsTotals totals;
    for (const char* file : {"vr_study.json", "default.json", "four_rooms.json", "loop.json", "mirror_hall.json",
                             "glass_gallery.json", "window_pair.json", "three_kinds.json", "tinted_window.json",
                             "crossing.json", "scanner_lab.json", "corridor.json", "lamp_hall.json"})
        steps_compare(file, steps_frame(128, 72), totals);
    std::printf("  %d frames, %d portal passes: %d one-draw marks, %d unmarks left out\n", totals.frames, totals.drawn,
                totals.one_draw, totals.skipped);
    EXPECT_GT(totals.one_draw, 0);
    EXPECT_LT(totals.one_draw, totals.drawn);
    EXPECT_GT(totals.skipped, 0);
    EXPECT_LT(totals.skipped, totals.drawn);
}

// The same with multisampling, two-pass stereo, standard depth, oblique
// clipping, portal textures and a deep limit.
TEST(PortalSteps, SameImageInEveryFrameMode) {
    StepsTotals totals;
    for (const char* file : {"vr_study.json", "mirror_hall.json", "three_kinds.json", "window_pair.json"}) {
        render::FrameDesc f = steps_frame(96, 54);
        f.samples = 4;
        steps_compare(file, f, totals);
        f = steps_frame(96, 54);
        f.stereo = render::StereoMode::TwoPass;
        steps_compare(file, f, totals);
        f = steps_frame(96, 54);
        f.depth = render::DepthMode::Standard;
        f.clip = render::ClipMode::Oblique;
        steps_compare(file, f, totals);
        f = steps_frame(96, 54);
        f.portal_texture_scale = 0.5;
        steps_compare(file, f, totals);
        f = steps_frame(96, 54);
        f.max_depth = 24;
        steps_compare(file, f, totals);
    }
    EXPECT_GT(totals.one_draw, 0);
    EXPECT_GT(totals.skipped, 0);
}

// Past kMaxBoxBitDepth the stencil has no room for the box bit: every mark
// takes the box and a quad again, the unmarks are still left out, and the
// image is the same as one limit below.
TEST(PortalSteps, NoBoxBitPastItsDepthLimit) {
    const layout::Layout l = testing::example_layout("vr_study.json");
    render::FrameDesc f = steps_frame(320, 180);
    f.room = l.start.room;
    f.head.position = l.start.position;
    f.head.yaw_deg = l.start.yaw_deg;
    f.max_depth = render::kMaxBoxBitDepth;
    render::FrameStats with_bit, without;
    const image::Image a = testing::render_once(gl::Backend::Egl, l, f, &with_bit);
    f.max_depth = render::kMaxBoxBitDepth + 1;
    const image::Image b = testing::render_once(gl::Backend::Egl, l, f, &without);
    EXPECT_EQ(testing::count_colour_differences(a, b), 0);
    EXPECT_EQ(testing::count_id_differences(a, b), 0);
    EXPECT_EQ(with_bit.one_draw_marks, 6);
    EXPECT_EQ(without.one_draw_marks, 0);
    EXPECT_EQ(without.unmarks_skipped, 6);
    EXPECT_EQ(without.draw_calls - with_bit.draw_calls, 6);
}

}  // namespace
}  // namespace impossible
