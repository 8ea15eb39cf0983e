// The per-context state cache: what it sets is what GL holds, it skips what GL
// holds already, renderers that share a context share it, and a frame leaves
// nothing of its renderer bound.
#include <gtest/gtest.h>

#include "gl/context.hpp"
#include "gl/handles.hpp"
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
    state.viewport_indexed(0, {1, 2, 3, 4});
    GLint vp[4] = {};
    glGetIntegeri_v(GL_VIEWPORT, 0, vp);
    EXPECT_EQ(vp[0], 1);
    EXPECT_EQ(vp[3], 4);
    state.viewport({0, 0, 8, 8});
    glGetIntegerv(GL_VIEWPORT, vp);
    EXPECT_EQ(vp[0], 0);
    EXPECT_EQ(vp[2], 8);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// The texture units and the read and draw framebuffers: a bind the cache
// already holds is not sent again (GL, changed behind the cache's back, keeps
// what it was given), a different one is, and invalidate() or
// deleting_texture()/deleting_framebuffer() make the next one be sent.
TEST(StateCache, SkipsRedundantTextureAndFramebufferBinds) {
    Result<gl::Context> context = gl::create_context(gl::Backend::Egl);
    ASSERT_TRUE(context) << context.error();
    gl::StateCache& state = context->state();
    gl::Texture a = gl::create_texture(GL_TEXTURE_2D), b = gl::create_texture(GL_TEXTURE_2D);
    glTextureStorage2D(a.get(), 1, GL_RGBA8, 4, 4);
    glTextureStorage2D(b.get(), 1, GL_RGBA8, 4, 4);
    const auto bound_2d = [](GLuint unit) {
        glActiveTexture(GL_TEXTURE0 + unit);
        return static_cast<GLuint>(get_int(GL_TEXTURE_BINDING_2D));
    };

    state.texture(1, a.get());
    EXPECT_EQ(bound_2d(1), a.get());
    glBindTextureUnit(1, b.get());  // behind the cache's back
    state.texture(1, a.get());      // redundant for the cache: not sent
    EXPECT_EQ(bound_2d(1), b.get());
    state.texture(1, 0);  // a change: sent
    EXPECT_EQ(bound_2d(1), 0u);
    state.texture(1, a.get());
    EXPECT_EQ(bound_2d(1), a.get());
    EXPECT_EQ(bound_2d(0), 0u);  // other units untouched
    glBindTextureUnit(1, b.get());
    state.deleting_texture(a.get());  // forgets unit 1: the next bind is sent
    state.texture(1, a.get());
    EXPECT_EQ(bound_2d(1), a.get());
    glBindTextureUnit(1, b.get());
    state.invalidate();
    state.texture(1, a.get());
    EXPECT_EQ(bound_2d(1), a.get());

    gl::Framebuffer f = gl::create_framebuffer(), g = gl::create_framebuffer();
    for (const bool read : {true, false}) {
        const GLenum target = read ? GL_READ_FRAMEBUFFER : GL_DRAW_FRAMEBUFFER;
        const GLenum binding = read ? GL_READ_FRAMEBUFFER_BINDING : GL_DRAW_FRAMEBUFFER_BINDING;
        const auto bind = [&](GLuint fb) { read ? state.read_framebuffer(fb) : state.draw_framebuffer(fb); };
        bind(f.get());
        EXPECT_EQ(static_cast<GLuint>(get_int(binding)), f.get()) << read;
        glBindFramebuffer(target, g.get());
        bind(f.get());  // redundant: not sent
        EXPECT_EQ(static_cast<GLuint>(get_int(binding)), g.get()) << read;
        bind(0);  // a change: sent
        EXPECT_EQ(get_int(binding), 0) << read;
        bind(f.get());
        EXPECT_EQ(static_cast<GLuint>(get_int(binding)), f.get()) << read;
        glBindFramebuffer(target, g.get());
        state.deleting_framebuffer(f.get());
        bind(f.get());
        EXPECT_EQ(static_cast<GLuint>(get_int(binding)), f.get()) << read;
    }
    // The read binding is its own: binding one leaves the other as it was.
    state.read_framebuffer(g.get());
    EXPECT_EQ(static_cast<GLuint>(get_int(GL_DRAW_FRAMEBUFFER_BINDING)), f.get());

    state.release_bindings();
    EXPECT_EQ(bound_2d(1), 0u);
    EXPECT_EQ(get_int(GL_READ_FRAMEBUFFER_BINDING), 0);
    EXPECT_EQ(get_int(GL_DRAW_FRAMEBUFFER_BINDING), 0);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// The indexed viewports: an index the cache holds is not sent again, and a
// plain viewport is skipped only when every tracked index holds it.
TEST(StateCache, SkipsRedundantViewports) {
    Result<gl::Context> context = gl::create_context(gl::Backend::Egl);
    ASSERT_TRUE(context) << context.error();
    gl::StateCache& state = context->state();
    const auto viewport = [](GLuint index) {
        GLint v[4] = {};
        glGetIntegeri_v(GL_VIEWPORT, index, v);
        return gl::WindowRect{v[0], v[1], v[2], v[3]};
    };
    state.viewport({0, 0, 16, 8});
    state.viewport_indexed(1, {8, 0, 8, 8});
    EXPECT_EQ(viewport(0), (gl::WindowRect{0, 0, 16, 8}));
    EXPECT_EQ(viewport(1), (gl::WindowRect{8, 0, 8, 8}));
    glViewportIndexedf(1, 0, 0, 1, 1);        // behind the cache's back
    state.viewport_indexed(1, {8, 0, 8, 8});  // redundant: not sent
    EXPECT_EQ(viewport(1), (gl::WindowRect{0, 0, 1, 1}));
    state.viewport({0, 0, 16, 8});  // index 1 differs: sent, to every index
    EXPECT_EQ(viewport(1), (gl::WindowRect{0, 0, 16, 8}));
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// Two renderers of different layouts on one context (as `impossible bench`
// does) draw exactly what each draws alone, in any order, and a frame leaves
// no program, vertex array, framebuffer or texture bound.
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
    Result<render::Renderer> ra = render::Renderer::create(context->state(), scene::build_scene(a));
    Result<render::Renderer> rb = render::Renderer::create(context->state(), scene::build_scene(b));
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
        EXPECT_EQ(get_int(GL_READ_FRAMEBUFFER_BINDING), 0);
        for (GLuint unit = 0; unit < static_cast<GLuint>(gl::kTextureUnits); ++unit) {
            glActiveTexture(GL_TEXTURE0 + unit);
            EXPECT_EQ(get_int(GL_TEXTURE_BINDING_2D), 0) << unit;
            EXPECT_EQ(get_int(GL_TEXTURE_BINDING_2D_MULTISAMPLE), 0) << unit;
        }
        glActiveTexture(GL_TEXTURE0);
    }
}

}  // namespace
}  // namespace impossible
