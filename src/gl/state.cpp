#include "gl/state.hpp"

#include <cassert>

namespace impossible::gl {
namespace {

void enable(GLenum cap, bool on) { on ? glEnable(cap) : glDisable(cap); }

void blend_func(Blend blend) {
    switch (blend) {
        case Blend::Replace: break;
        case Blend::AlphaOver:
            glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
            break;
        case Blend::ScaleTarget: glBlendFunc(GL_ZERO, GL_CONSTANT_COLOR); break;
        case Blend::AddScaledTarget: glBlendFunc(GL_ONE, GL_CONSTANT_COLOR); break;
    }
}

}  // namespace

void StateCache::invalidate() {
    known_ = false;
    blend_color_known_ = false;
    scissor_known_ = false;
    for (bool& known : viewport_known_) known = false;
    program_ = vertex_array_ = draw_framebuffer_ = read_framebuffer_ = draw_indirect_buffer_ = clip_depth_ = kUnknown;
    for (GLuint& t : textures_) t = kUnknown;
}

void StateCache::apply(const PassState& s, GLint stencil_ref) {
    assert(s.clip_distances >= 0 && s.clip_distances <= kMaxClipDistances);
    const bool all = !known_;
    if (all || s.front_clockwise != state_.front_clockwise) glFrontFace(s.front_clockwise ? GL_CW : GL_CCW);
    if (all || s.depth_test != state_.depth_test) enable(GL_DEPTH_TEST, s.depth_test);
    if (all || s.depth_write != state_.depth_write) glDepthMask(s.depth_write ? GL_TRUE : GL_FALSE);
    if (all || s.depth_func != state_.depth_func) glDepthFunc(s.depth_func);
    if (all || s.color_mask != state_.color_mask || s.write_ids != state_.write_ids) {
        const GLuint m = s.color_mask;
        glColorMask((m & 1u) != 0, (m & 2u) != 0, (m & 4u) != 0, (m & 8u) != 0);
        if (!s.write_ids) glColorMaski(1, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    }
    if (all || s.cull_back_faces != state_.cull_back_faces) {
        enable(GL_CULL_FACE, s.cull_back_faces);
        if (all) glCullFace(GL_BACK);
    }
    const StencilState& t = s.stencil;
    if (all || t.enabled != state_.stencil.enabled) enable(GL_STENCIL_TEST, t.enabled);
    if (all || t.func != state_.stencil.func || t.read_mask != state_.stencil.read_mask || stencil_ref != stencil_ref_)
        glStencilFunc(t.func, stencil_ref, t.read_mask);
    if (all || t.fail != state_.stencil.fail || t.depth_fail != state_.stencil.depth_fail ||
        t.pass != state_.stencil.pass)
        glStencilOp(t.fail, t.depth_fail, t.pass);
    if (all || t.write_mask != state_.stencil.write_mask) glStencilMask(t.write_mask);
    for (int i = 0; i < kMaxClipDistances; ++i) {
        const bool on = i < s.clip_distances, was = i < state_.clip_distances;
        if (all || on != was) enable(GL_CLIP_DISTANCE0 + i, on);
    }
    if (all || (s.blend == Blend::Replace) != (state_.blend == Blend::Replace))
        enable(GL_BLEND, s.blend != Blend::Replace);
    if (s.blend != Blend::Replace && (all || s.blend != state_.blend)) blend_func(s.blend);
    const bool offset = s.offset_factor != 0.0f || s.offset_units != 0.0f;
    const bool had_offset = state_.offset_factor != 0.0f || state_.offset_units != 0.0f;
    if (all || offset != had_offset) enable(GL_POLYGON_OFFSET_FILL, offset);
    if (offset && (all || s.offset_factor != state_.offset_factor || s.offset_units != state_.offset_units))
        glPolygonOffset(s.offset_factor, s.offset_units);
    state_ = s;
    stencil_ref_ = stencil_ref;
    known_ = true;
}

void StateCache::blend_color(float r, float g, float b, float a) {
    const float c[4] = {r, g, b, a};
    if (blend_color_known_ && c[0] == blend_color_[0] && c[1] == blend_color_[1] && c[2] == blend_color_[2] &&
        c[3] == blend_color_[3])
        return;
    glBlendColor(r, g, b, a);
    for (int i = 0; i < 4; ++i) blend_color_[i] = c[i];
    blend_color_known_ = true;
}

void StateCache::scissor(const WindowRect& rect) {
    if (!scissor_known_ || !scissor_on_) glEnable(GL_SCISSOR_TEST);
    if (!scissor_known_ || !(rect == scissor_)) glScissor(rect.x, rect.y, rect.width, rect.height);
    scissor_on_ = true;
    scissor_known_ = true;
    scissor_ = rect;
}

void StateCache::no_scissor() {
    if (!scissor_known_ || scissor_on_) glDisable(GL_SCISSOR_TEST);
    scissor_on_ = false;
    scissor_known_ = true;
}

void StateCache::viewport(const WindowRect& rect) {
    bool same = true;
    for (int i = 0; i < kViewports; ++i) same = same && viewport_known_[i] && viewport_[i] == rect;
    if (same) return;
    glViewport(rect.x, rect.y, rect.width, rect.height);
    for (int i = 0; i < kViewports; ++i) {
        viewport_[i] = rect;
        viewport_known_[i] = true;
    }
}

void StateCache::viewport_indexed(GLuint index, const WindowRect& rect) {
    assert(index < static_cast<GLuint>(kViewports));
    if (viewport_known_[index] && viewport_[index] == rect) return;
    glViewportIndexedf(index, static_cast<float>(rect.x), static_cast<float>(rect.y), static_cast<float>(rect.width),
                       static_cast<float>(rect.height));
    viewport_[index] = rect;
    viewport_known_[index] = true;
}

void StateCache::program(GLuint program) {
    if (program == program_) return;
    glUseProgram(program);
    program_ = program;
}

void StateCache::vertex_array(GLuint vertex_array) {
    if (vertex_array == vertex_array_) return;
    glBindVertexArray(vertex_array);
    vertex_array_ = vertex_array;
}

void StateCache::draw_framebuffer(GLuint framebuffer) {
    if (framebuffer == draw_framebuffer_) return;
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    draw_framebuffer_ = framebuffer;
}

void StateCache::read_framebuffer(GLuint framebuffer) {
    if (framebuffer == read_framebuffer_) return;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    read_framebuffer_ = framebuffer;
}

void StateCache::draw_indirect_buffer(GLuint buffer) {
    if (buffer == draw_indirect_buffer_) return;
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, buffer);
    draw_indirect_buffer_ = buffer;
}

void StateCache::texture(GLuint unit, GLuint texture) {
    assert(unit < static_cast<GLuint>(kTextureUnits));
    if (texture == textures_[unit]) return;
    glBindTextureUnit(unit, texture);
    textures_[unit] = texture;
}

void StateCache::deleting_texture(GLuint texture) {
    for (GLuint& t : textures_)
        if (t == texture) t = kUnknown;
}

void StateCache::deleting_framebuffer(GLuint framebuffer) {
    if (draw_framebuffer_ == framebuffer) draw_framebuffer_ = kUnknown;
    if (read_framebuffer_ == framebuffer) read_framebuffer_ = kUnknown;
}

void StateCache::release_bindings() {
    vertex_array(0);
    program(0);
    draw_framebuffer(0);
    read_framebuffer(0);
    draw_indirect_buffer(0);
    for (int unit = 0; unit < kTextureUnits; ++unit) texture(static_cast<GLuint>(unit), 0);
}

void StateCache::clip_control(GLenum depth) {
    if (depth == clip_depth_) return;
    glClipControl(GL_LOWER_LEFT, depth);
    clip_depth_ = depth;
}

}  // namespace impossible::gl
