// Fixed-function state as plain data, applied through one shadow cache that
// compares before it calls GL. Render code describes each pass with one
// immutable PassState and never calls glEnable/glDepthFunc/... itself.
#pragma once

#include "gl/gl.hpp"

namespace impossible::gl {

struct StencilState {
    bool enabled = false;
    GLenum func = GL_ALWAYS;   // compared against the reference given with apply()
    GLuint read_mask = 0xff;
    GLenum fail = GL_KEEP, depth_fail = GL_KEEP, pass = GL_KEEP;
    GLuint write_mask = 0xff;
    bool operator==(const StencilState&) const = default;
};

struct PassState {
    bool depth_test = true;
    bool depth_write = true;
    GLenum depth_func = GL_GREATER;  // reversed-Z: nearer is greater
    bool color_write = true;         // all colour attachments
    bool cull_back_faces = true;
    StencilState stencil;
    bool operator==(const PassState&) const = default;
};

struct ScissorRect {
    int x = 0, y = 0, width = 0, height = 0;  // GL window coordinates (origin bottom-left)
    bool operator==(const ScissorRect&) const = default;
};

class StateCache {
public:
    // Forgets what GL holds, so that the next apply() sets everything.
    void invalidate() {
        known_ = false;
        scissor_known_ = false;
    }
    void apply(const PassState& state, GLint stencil_ref);
    void scissor(const ScissorRect& rect);  // enables the scissor test
    void no_scissor();

private:
    bool known_ = false;
    PassState state_;
    GLint stencil_ref_ = 0;
    bool scissor_on_ = false;
    bool scissor_known_ = false;
    ScissorRect scissor_;
};

}  // namespace impossible::gl
