#include "gl/state.hpp"

namespace impossible::gl {
namespace {

void enable(GLenum cap, bool on) { on ? glEnable(cap) : glDisable(cap); }

}  // namespace

void StateCache::apply(const PassState& s, GLint stencil_ref) {
    const bool all = !known_;
    if (all || s.depth_test != state_.depth_test) enable(GL_DEPTH_TEST, s.depth_test);
    if (all || s.depth_write != state_.depth_write) glDepthMask(s.depth_write ? GL_TRUE : GL_FALSE);
    if (all || s.depth_func != state_.depth_func) glDepthFunc(s.depth_func);
    if (all || s.color_write != state_.color_write) {
        const GLboolean c = s.color_write ? GL_TRUE : GL_FALSE;
        glColorMask(c, c, c, c);
    }
    if (all || s.cull_back_faces != state_.cull_back_faces) {
        enable(GL_CULL_FACE, s.cull_back_faces);
        if (all) glCullFace(GL_BACK);
    }
    const StencilState& t = s.stencil;
    if (all || t.enabled != state_.stencil.enabled) enable(GL_STENCIL_TEST, t.enabled);
    if (all || t.func != state_.stencil.func || t.read_mask != state_.stencil.read_mask ||
        stencil_ref != stencil_ref_)
        glStencilFunc(t.func, stencil_ref, t.read_mask);
    if (all || t.fail != state_.stencil.fail || t.depth_fail != state_.stencil.depth_fail ||
        t.pass != state_.stencil.pass)
        glStencilOp(t.fail, t.depth_fail, t.pass);
    if (all || t.write_mask != state_.stencil.write_mask) glStencilMask(t.write_mask);
    state_ = s;
    stencil_ref_ = stencil_ref;
    known_ = true;
}

void StateCache::scissor(const ScissorRect& rect) {
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

}  // namespace impossible::gl
