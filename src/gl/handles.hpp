// Move-only owners of GL object names. An empty handle holds 0; destroying a
// handle deletes its object. Each is created with the DSA glCreate* calls.
#pragma once

#include <utility>

#include "gl/gl.hpp"

namespace impossible::gl {

template <void (*Delete)(GLuint)>
class Handle {
public:
    Handle() = default;
    explicit Handle(GLuint name) : name_(name) {}
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    Handle(Handle&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
    Handle& operator=(Handle&& other) noexcept {
        if (this != &other) {
            reset();
            name_ = std::exchange(other.name_, 0);
        }
        return *this;
    }
    ~Handle() { reset(); }

    GLuint get() const { return name_; }
    explicit operator bool() const { return name_ != 0; }
    void reset() {
        if (name_) Delete(name_);
        name_ = 0;
    }

private:
    GLuint name_ = 0;
};

namespace detail {
inline void delete_buffer(GLuint n) { glDeleteBuffers(1, &n); }
inline void delete_vertex_array(GLuint n) { glDeleteVertexArrays(1, &n); }
inline void delete_texture(GLuint n) { glDeleteTextures(1, &n); }
inline void delete_renderbuffer(GLuint n) { glDeleteRenderbuffers(1, &n); }
inline void delete_framebuffer(GLuint n) { glDeleteFramebuffers(1, &n); }
inline void delete_query(GLuint n) { glDeleteQueries(1, &n); }
inline void delete_program(GLuint n) { glDeleteProgram(n); }
inline void delete_shader(GLuint n) { glDeleteShader(n); }
}  // namespace detail

using Buffer = Handle<detail::delete_buffer>;
using VertexArray = Handle<detail::delete_vertex_array>;
using Texture = Handle<detail::delete_texture>;
using Renderbuffer = Handle<detail::delete_renderbuffer>;
using Framebuffer = Handle<detail::delete_framebuffer>;
using Query = Handle<detail::delete_query>;
using Program = Handle<detail::delete_program>;
using Shader = Handle<detail::delete_shader>;

inline Buffer create_buffer() {
    GLuint n = 0;
    glCreateBuffers(1, &n);
    return Buffer(n);
}
inline VertexArray create_vertex_array() {
    GLuint n = 0;
    glCreateVertexArrays(1, &n);
    return VertexArray(n);
}
inline Texture create_texture(GLenum target) {
    GLuint n = 0;
    glCreateTextures(target, 1, &n);
    return Texture(n);
}
inline Renderbuffer create_renderbuffer() {
    GLuint n = 0;
    glCreateRenderbuffers(1, &n);
    return Renderbuffer(n);
}
inline Framebuffer create_framebuffer() {
    GLuint n = 0;
    glCreateFramebuffers(1, &n);
    return Framebuffer(n);
}
inline Query create_query(GLenum target) {
    GLuint n = 0;
    glCreateQueries(target, 1, &n);
    return Query(n);
}

}  // namespace impossible::gl
