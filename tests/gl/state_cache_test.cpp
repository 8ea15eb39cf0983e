// The per-context state cache: what it sets is what GL holds, renderers that
// share a context share it, and a frame leaves nothing of its renderer bound.
#include <gtest/gtest.h>

#include "gl/context.hpp"
#include "gl/state.hpp"
#include "gl_fixture.hpp"

namespace impossible {
namespace {

GLint get_int(GLenum name) {
    GLint v = 0;
    glGetIntegerv(name, &v);
    return v;
}

TEST(StateCache, WhatItAppliesIsWhatGlHolds) {
    Result<gl::Context> context = gl::create_context(gl::Backend::Egl);
    ASSERT_TRUE(context) << context.error();
    gl::StateCache& state = context->state();
    gl::PassState s;
    s.clip_distances = 5;
    s.depth_func = GL_LEQUAL;
    state.apply(s, 0);
    for (int i = 0; i < 5; ++i) EXPECT_TRUE(glIsEnabled(GL_CLIP_DISTANCE0 + i)) << i;
    EXPECT_FALSE(glIsEnabled(GL_CLIP_DISTANCE0 + 5));
    EXPECT_FALSE(glIsEnabled(GL_BLEND));
    EXPECT_EQ(get_int(GL_DEPTH_FUNC), GL_LEQUAL);

    state.apply(gl::plain_2d_state(true, gl::color_channels(true, false, false, true)), 0);
    for (int i = 0; i < 5; ++i) EXPECT_FALSE(glIsEnabled(GL_CLIP_DISTANCE0 + i)) << i;
    EXPECT_TRUE(glIsEnabled(GL_BLEND));
    EXPECT_FALSE(glIsEnabled(GL_DEPTH_TEST));
    EXPECT_EQ(get_int(GL_BLEND_SRC_RGB), GL_SRC_ALPHA);
    GLboolean mask[4] = {};
    glGetBooleanv(GL_COLOR_WRITEMASK, mask);
    EXPECT_TRUE(mask[0] && !mask[1] && !mask[2] && mask[3]);

    // An indexed viewport makes the next plain one be sent again.
    state.viewport({0, 0, 8, 8});
    state.viewport_indexed(0, 1.0f, 2.0f, 3.0f, 4.0f);
    state.viewport({0, 0, 8, 8});
    GLint vp[4] = {};
    glGetIntegerv(GL_VIEWPORT, vp);
    EXPECT_EQ(vp[0], 0);
    EXPECT_EQ(vp[2], 8);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// Two renderers of different layouts on one context (as `impossible bench`
// does) draw exactly what each draws alone, in any order, and a frame leaves
// no program, vertex array or draw framebuffer bound.
TEST(StateCache, RenderersSharingAContextDrawAsAlone) {
    const layout::Layout a = testing::layout_from_file(std::string(IMPOSSIBLE_TEST_DATA) + "/layouts/impossible.json");
    const layout::Layout b = testing::layout_from_text(testing::kSingleRoom);
    render::FrameDesc fa, fb;
    fa.head.position = a.start.position;
    fa.room = a.start.room;
    fb.head.position = b.start.position;
    fa.eye_width = fb.eye_width = 64;
    fa.eye_height = fb.eye_height = 48;
    const image::Image alone_a = testing::render_once(gl::Backend::Egl, a, fa);
    const image::Image alone_b = testing::render_once(gl::Backend::Egl, b, fb);

    Result<gl::Context> context = gl::create_context(gl::Backend::Egl);
    ASSERT_TRUE(context) << context.error();
    Result<render::Renderer> ra = render::Renderer::create(context->state(), a, scene::build_scene(a));
    Result<render::Renderer> rb = render::Renderer::create(context->state(), b, scene::build_scene(b));
    ASSERT_TRUE(ra && rb);
    for (int round = 0; round < 2; ++round) {
        Result<render::RenderedFrame> ia = ra->render(fa);
        Result<render::RenderedFrame> ib = rb->render(fb);
        ASSERT_TRUE(ia && ib);
        EXPECT_EQ(ia->image.rgb, alone_a.rgb) << round;
        EXPECT_EQ(ia->image.ids, alone_a.ids) << round;
        EXPECT_EQ(ib->image.rgb, alone_b.rgb) << round;
        EXPECT_EQ(get_int(GL_CURRENT_PROGRAM), 0);
        EXPECT_EQ(get_int(GL_VERTEX_ARRAY_BINDING), 0);
        EXPECT_EQ(get_int(GL_DRAW_FRAMEBUFFER_BINDING), 0);
    }
}

}  // namespace
}  // namespace impossible
