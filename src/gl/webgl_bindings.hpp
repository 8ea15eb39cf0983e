// The web build's record of what is bound (gl/webgl.cpp), shared by the
// files that map GL 4.5 calls onto WebGL 2. Emscripten only.
#pragma once

#include <unordered_map>

#include "gl/webgl.hpp"

// The real ES entry points, which the header's macros hide.
#undef glUseProgram
#undef glEnable
#undef glDisable
#undef glBindVertexArray
#undef glBindFramebuffer
#undef glBindBuffer
#undef glActiveTexture
#undef glBindTexture
#undef glDeleteBuffers
#undef glDeleteTextures
#undef glDeleteVertexArrays
#undef glBindBufferBase

namespace impossible::gl::webgl {

// What is bound, as the trackers saw it.
struct Bindings {
    GLuint program = 0;
    GLuint vertex_array = 0;
    GLuint draw_framebuffer = 0;
    GLuint read_framebuffer = 0;
    GLenum active_unit = GL_TEXTURE0;
    bool scissor = false;                        // glIsEnabled waits for the GPU process: known here instead
    std::unordered_map<GLenum, GLuint> buffers;  // target -> buffer
};

Bindings& bound_now();

// The target a texture was made for (GL_TEXTURE_2D when unknown).
GLenum target_of(GLuint texture);

// Binds `framebuffer` as the draw framebuffer for the duration of `act`.
template <typename F>
void with_draw_framebuffer(GLuint framebuffer, F&& act) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
    act();
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, bound_now().draw_framebuffer);
}

}  // namespace impossible::gl::webgl
