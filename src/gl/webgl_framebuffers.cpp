// The web build's framebuffer and renderbuffer calls of GL 4.5 on WebGL 2
// (gl/webgl.hpp). Compiled only by emscripten; the native build's file is
// empty.
#if defined(__EMSCRIPTEN__)

#include "gl/webgl_bindings.hpp"

namespace impossible::gl::webgl {

void named_renderbuffer_storage(GLuint renderbuffer, GLenum format, GLsizei width, GLsizei height) {
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer);
    glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
}
void named_renderbuffer_storage_multisample(GLuint renderbuffer, GLsizei samples, GLenum format, GLsizei width,
                                            GLsizei height) {
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
}

void named_framebuffer_texture(GLuint framebuffer, GLenum attachment, GLuint texture, GLint level) {
    with_draw_framebuffer(framebuffer, [&] {
        glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, attachment, target_of(texture), texture, level);
    });
}
void named_framebuffer_texture_layer(GLuint framebuffer, GLenum attachment, GLuint texture, GLint level, GLint layer) {
    with_draw_framebuffer(framebuffer,
                          [&] { glFramebufferTextureLayer(GL_DRAW_FRAMEBUFFER, attachment, texture, level, layer); });
}
void named_framebuffer_renderbuffer(GLuint framebuffer, GLenum attachment, GLenum target, GLuint renderbuffer) {
    with_draw_framebuffer(framebuffer,
                          [&] { glFramebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, attachment, target, renderbuffer); });
}
void named_framebuffer_draw_buffers(GLuint framebuffer, GLsizei n, const GLenum* buffers) {
    with_draw_framebuffer(framebuffer, [&] { glDrawBuffers(n, buffers); });
}
void named_framebuffer_draw_buffer(GLuint framebuffer, GLenum buffer) {
    // ES: the i-th entry names attachment i or nothing.
    std::vector<GLenum> list;
    if (buffer >= GL_COLOR_ATTACHMENT0 && buffer < GL_COLOR_ATTACHMENT0 + 8) {
        list.assign(buffer - GL_COLOR_ATTACHMENT0 + 1, GL_NONE);
        list.back() = buffer;
    } else {
        list.push_back(buffer);
    }
    named_framebuffer_draw_buffers(framebuffer, static_cast<GLsizei>(list.size()), list.data());
}
void named_framebuffer_read_buffer(GLuint framebuffer, GLenum buffer) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glReadBuffer(buffer);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, bound_now().read_framebuffer);
}
GLenum check_named_framebuffer_status(GLuint framebuffer, GLenum target) {
    GLenum status = 0;
    with_draw_framebuffer(framebuffer, [&] { status = glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER); });
    (void)target;
    return status;
}
void clear_named_framebuffer_fv(GLuint framebuffer, GLenum buffer, GLint drawbuffer, const GLfloat* value) {
    with_draw_framebuffer(framebuffer, [&] { glClearBufferfv(buffer, drawbuffer, value); });
}
void clear_named_framebuffer_uiv(GLuint framebuffer, GLenum buffer, GLint drawbuffer, const GLuint* value) {
    with_draw_framebuffer(framebuffer, [&] { glClearBufferuiv(buffer, drawbuffer, value); });
}
void clear_named_framebuffer_fi(GLuint framebuffer, GLenum buffer, GLint drawbuffer, GLfloat depth, GLint stencil) {
    with_draw_framebuffer(framebuffer, [&] { glClearBufferfi(buffer, drawbuffer, depth, stencil); });
}
void blit_named_framebuffer(GLuint from, GLuint to, GLint x0, GLint y0, GLint x1, GLint y1, GLint u0, GLint v0,
                            GLint u1, GLint v1, GLbitfield mask, GLenum filter) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, from);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, to);
    glBlitFramebuffer(x0, y0, x1, y1, u0, v0, u1, v1, mask, filter);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, bound_now().read_framebuffer);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, bound_now().draw_framebuffer);
}

void copy_image_sub_data(GLuint from, GLenum from_target, GLint from_level, GLint x, GLint y, GLint, GLuint to,
                         GLenum to_target, GLint to_level, GLint u, GLint v, GLint, GLsizei width, GLsizei height,
                         GLsizei) {
    static GLuint read = 0, draw = 0;
    if (!read) {
        glGenFramebuffers(1, &read);
        glGenFramebuffers(1, &draw);
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, read);
    if (from_target == GL_RENDERBUFFER)
        glFramebufferRenderbuffer(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, from);
    else
        glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, from_target, from, from_level);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, draw);
    glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, to_target, to, to_level);
    const bool scissor = bound_now().scissor;
    if (scissor) glDisable(GL_SCISSOR_TEST);
    glBlitFramebuffer(x, y, x + width, y + height, u, v, u + width, v + height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    if (scissor) glEnable(GL_SCISSOR_TEST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, bound_now().read_framebuffer);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, bound_now().draw_framebuffer);
}
}  // namespace impossible::gl::webgl

#endif  // __EMSCRIPTEN__
