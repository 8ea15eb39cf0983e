// The web build's GL 4.5 calls on WebGL 2 (gl/webgl.hpp). Compiled only by
// emscripten; the native build's file is empty.
#if defined(__EMSCRIPTEN__)

#include "gl/webgl.hpp"
#include "gl/webgl_bindings.hpp"

#include <emscripten.h>

#include <cstdio>
#include <cstdlib>
#include <unordered_map>
#include <vector>

// WebGL's extensions, called on the context emscripten made current (GLctx).
// JavaScript, which clang-format would break:
// clang-format off
EM_JS(void, impossible_clip_control, (int origin, int depth), {
    const e = GLctx.getExtension('EXT_clip_control');
    e.clipControlEXT(origin === 0x8CA1 ? e.LOWER_LEFT_EXT : e.UPPER_LEFT_EXT,
                     depth === 0x935F ? e.ZERO_TO_ONE_EXT : e.NEGATIVE_ONE_TO_ONE_EXT);
});
EM_JS(void, impossible_color_mask_i, (int index, int r, int g, int b, int a), {
    GLctx.getExtension('OES_draw_buffers_indexed').colorMaskiOES(index, !!r, !!g, !!b, !!a);
});
EM_JS(int, impossible_has_extension, (const char* name), {
    return GLctx.getExtension(UTF8ToString(name)) ? 1 : 0;
});
// clang-format on

namespace impossible::gl::webgl {
namespace {

// Per texture, its target; per buffer, whether it is an index buffer (WebGL
// types a buffer by its first binding, and an index buffer can be bound
// nowhere else); per vertex array, its attributes' formats and its bindings'
// buffers, from which glVertexAttribPointer is made (ES 3.0 has no separate
// attribute formats).
std::unordered_map<GLuint, GLenum> texture_targets;
std::unordered_map<GLuint, bool> index_buffers;
struct AttribFormat {
    GLint size = 4;
    GLenum type = GL_FLOAT;
    GLboolean normalized = GL_FALSE;
    GLuint offset = 0;
    GLuint binding = 0;
};
struct BufferBinding {
    GLuint buffer = 0;
    GLintptr offset = 0;
    GLsizei stride = 0;
};
struct VertexArrayState {
    std::unordered_map<GLuint, AttribFormat> attribs;
    std::unordered_map<GLuint, BufferBinding> bindings;
};
std::unordered_map<GLuint, VertexArrayState> vertex_arrays;
Extensions found;

// The texture unit the compatibility calls bind textures on to edit them:
// the last one, which no program samples.
constexpr GLenum kEditUnit = GL_TEXTURE0 + 15;

}  // namespace

Bindings& bound_now() {
    static Bindings bound;
    return bound;
}

GLenum target_of(GLuint texture) {
    const auto it = texture_targets.find(texture);
    return it == texture_targets.end() ? GL_TEXTURE_2D : it->second;
}

// Binds `texture` on the edit unit for the duration of `act`.
namespace {

Bindings& bound = bound_now();

template <typename F>
void with_texture(GLuint texture, F&& act) {
    glActiveTexture(kEditUnit);
    glBindTexture(target_of(texture), texture);
    act(target_of(texture));
    glBindTexture(target_of(texture), 0);
    glActiveTexture(bound.active_unit);
}

// Binds `buffer` for the duration of `act` to a target WebGL lets it have.
template <typename F>
void with_buffer(GLuint buffer, F&& act) {
    glBindBuffer(GL_COPY_WRITE_BUFFER, buffer);
    act(GL_COPY_WRITE_BUFFER);
    const auto it = bound.buffers.find(GL_COPY_WRITE_BUFFER);
    glBindBuffer(GL_COPY_WRITE_BUFFER, it == bound.buffers.end() ? 0 : it->second);
}

template <typename F>
void with_index_buffer(GLuint buffer, F&& act) {
    // A vertex array of the compatibility layer's own holds the index buffer
    // while it is edited, so that no vertex array of the renderer changes.
    static GLuint scratch = 0;
    if (!scratch) glGenVertexArrays(1, &scratch);
    glBindVertexArray(scratch);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffer);
    act(GL_ELEMENT_ARRAY_BUFFER);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    glBindVertexArray(bound.vertex_array);
}

template <typename F>
void with_any_buffer(GLuint buffer, F&& act) {
    if (index_buffers[buffer])
        with_index_buffer(buffer, act);
    else
        with_buffer(buffer, act);
}

template <typename F>
void with_vertex_array(GLuint vao, F&& act) {
    glBindVertexArray(vao);
    act();
    glBindVertexArray(bound.vertex_array);
}

void apply_attrib(GLuint vao, GLuint index) {
    VertexArrayState& s = vertex_arrays[vao];
    const AttribFormat& f = s.attribs[index];
    const auto b = s.bindings.find(f.binding);
    if (b == s.bindings.end() || b->second.buffer == 0) return;
    with_vertex_array(vao, [&] {
        glBindBuffer(GL_ARRAY_BUFFER, b->second.buffer);
        glVertexAttribPointer(index, f.size, f.type, f.normalized, b->second.stride,
                              reinterpret_cast<const void*>(b->second.offset + f.offset));
        const auto it = bound.buffers.find(GL_ARRAY_BUFFER);
        glBindBuffer(GL_ARRAY_BUFFER, it == bound.buffers.end() ? 0 : it->second);
    });
}

}  // namespace

const Extensions& extensions() { return found; }

void read_extensions() {
    found.clip_distance = impossible_has_extension("WEBGL_clip_cull_distance") != 0;
    found.clip_control = impossible_has_extension("EXT_clip_control") != 0;
    found.draw_buffers_indexed = impossible_has_extension("OES_draw_buffers_indexed") != 0;
    found.float_blend = impossible_has_extension("EXT_float_blend") != 0;
    // The page has one WebGL context, which every gl::Context made on it
    // shares (gl/context_web.cpp): what is known of its objects stays, and
    // the bindings are put back to none, as each new state cache assumes.
    glUseProgram(0);
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glActiveTexture(GL_TEXTURE0);
    glDisable(GL_SCISSOR_TEST);
    bound = Bindings{};
}

GLuint current_program() { return bound.program; }

void use_program(GLuint program) {
    glUseProgram(program);
    bound.program = program;
}
void enable(GLenum cap) {
    glEnable(cap);
    if (cap == GL_SCISSOR_TEST) bound.scissor = true;
}
void disable(GLenum cap) {
    glDisable(cap);
    if (cap == GL_SCISSOR_TEST) bound.scissor = false;
}
void bind_vertex_array(GLuint vao) {
    glBindVertexArray(vao);
    bound.vertex_array = vao;
}
void bind_framebuffer(GLenum target, GLuint framebuffer) {
    glBindFramebuffer(target, framebuffer);
    if (target == GL_FRAMEBUFFER || target == GL_DRAW_FRAMEBUFFER) bound.draw_framebuffer = framebuffer;
    if (target == GL_FRAMEBUFFER || target == GL_READ_FRAMEBUFFER) bound.read_framebuffer = framebuffer;
}
void bind_buffer(GLenum target, GLuint buffer) {
    if (target == GL_DRAW_INDIRECT_BUFFER) return;  // nothing draws indirectly on the web
    glBindBuffer(target, buffer);
    if (target != GL_ELEMENT_ARRAY_BUFFER) bound.buffers[target] = buffer;
}
void active_texture(GLenum unit) {
    glActiveTexture(unit);
    bound.active_unit = unit;
}
void bind_texture(GLenum target, GLuint texture) { glBindTexture(target, texture); }

void create_buffers(GLsizei n, GLuint* names) { glGenBuffers(n, names); }
void create_vertex_arrays(GLsizei n, GLuint* names) { glGenVertexArrays(n, names); }
void create_textures(GLenum target, GLsizei n, GLuint* names) {
    glGenTextures(n, names);
    // Cube map arrays (the shadow maps) are 2D arrays of six layers a cube:
    // shadow_lookup.frag.glsl's WEBGL branch picks the face itself.
    if (target == GL_TEXTURE_CUBE_MAP_ARRAY) target = GL_TEXTURE_2D_ARRAY;
    for (GLsizei i = 0; i < n; ++i) texture_targets[names[i]] = target;
}
void create_renderbuffers(GLsizei n, GLuint* names) { glGenRenderbuffers(n, names); }
void create_framebuffers(GLsizei n, GLuint* names) { glGenFramebuffers(n, names); }
void create_queries(GLenum, GLsizei n, GLuint* names) { glGenQueries(n, names); }
void delete_buffers(GLsizei n, const GLuint* names) {
    for (GLsizei i = 0; i < n; ++i) index_buffers.erase(names[i]);
    glDeleteBuffers(n, names);
}
void delete_textures(GLsizei n, const GLuint* names) {
    for (GLsizei i = 0; i < n; ++i) texture_targets.erase(names[i]);
    glDeleteTextures(n, names);
}
void delete_vertex_arrays(GLsizei n, const GLuint* names) {
    for (GLsizei i = 0; i < n; ++i) vertex_arrays.erase(names[i]);
    glDeleteVertexArrays(n, names);
}

void named_buffer_data(GLuint buffer, GLsizeiptr size, const void* data, GLenum usage) {
    with_any_buffer(buffer, [&](GLenum t) {
        if (size >= kUniformBufferBytes || index_buffers[buffer]) {
            glBufferData(t, size, data, usage);
            return;
        }
        glBufferData(t, kUniformBufferBytes, nullptr, usage);
        if (data && size > 0) glBufferSubData(t, 0, size, data);
    });
}
void named_buffer_storage(GLuint buffer, GLsizeiptr size, const void* data, GLbitfield) {
    named_buffer_data(buffer, size, data, GL_STATIC_DRAW);
}
void bind_buffer_base(GLenum target, GLuint index, GLuint buffer) {
    glBindBufferBase(target == GL_SHADER_STORAGE_BUFFER ? GL_UNIFORM_BUFFER : target, index, buffer);
    bound.buffers[GL_UNIFORM_BUFFER] = buffer;
}
void named_buffer_sub_data(GLuint buffer, GLintptr offset, GLsizeiptr size, const void* data) {
    with_any_buffer(buffer, [&](GLenum t) { glBufferSubData(t, offset, size, data); });
}

void texture_storage_2d(GLuint texture, GLsizei levels, GLenum format, GLsizei width, GLsizei height) {
    with_texture(texture, [&](GLenum t) { glTexStorage2D(t, levels, format, width, height); });
}
void texture_storage_3d(GLuint texture, GLsizei levels, GLenum format, GLsizei width, GLsizei height, GLsizei depth) {
    with_texture(texture, [&](GLenum t) { glTexStorage3D(t, levels, format, width, height, depth); });
}
void texture_storage_2d_multisample(GLuint, GLsizei, GLenum, GLsizei, GLsizei, GLboolean) {
    unsupported("glTextureStorage2DMultisample");
}
void texture_sub_image_2d(GLuint texture, GLint level, GLint x, GLint y, GLsizei width, GLsizei height, GLenum format,
                          GLenum type, const void* pixels) {
    with_texture(texture, [&](GLenum t) { glTexSubImage2D(t, level, x, y, width, height, format, type, pixels); });
}
void texture_parameter_i(GLuint texture, GLenum name, GLint value) {
    with_texture(texture, [&](GLenum t) { glTexParameteri(t, name, value); });
}
void texture_parameter_fv(GLuint texture, GLenum name, const GLfloat* value) {
    with_texture(texture, [&](GLenum t) { glTexParameterfv(t, name, value); });
}
void generate_texture_mipmap(GLuint texture) {
    with_texture(texture, [&](GLenum t) { glGenerateMipmap(t); });
}
void bind_texture_unit(GLuint unit, GLuint texture) {
    glActiveTexture(GL_TEXTURE0 + unit);
    if (texture == 0) {
        for (GLenum t : {GL_TEXTURE_2D, GL_TEXTURE_2D_ARRAY, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP}) glBindTexture(t, 0);
    } else {
        glBindTexture(target_of(texture), texture);
    }
    glActiveTexture(bound.active_unit);
}

void vertex_array_vertex_buffer(GLuint vao, GLuint binding, GLuint buffer, GLintptr offset, GLsizei stride) {
    vertex_arrays[vao].bindings[binding] = {buffer, offset, stride};
    for (const auto& [index, format] : vertex_arrays[vao].attribs)
        if (format.binding == binding) apply_attrib(vao, index);
}
void vertex_array_element_buffer(GLuint vao, GLuint buffer) {
    index_buffers[buffer] = true;
    with_vertex_array(vao, [&] { glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffer); });
}
void enable_vertex_array_attrib(GLuint vao, GLuint index) {
    with_vertex_array(vao, [&] { glEnableVertexAttribArray(index); });
}
void vertex_array_attrib_format(GLuint vao, GLuint index, GLint size, GLenum type, GLboolean normalized,
                                GLuint offset) {
    AttribFormat& f = vertex_arrays[vao].attribs[index];
    f.size = size;
    f.type = type;
    f.normalized = normalized;
    f.offset = offset;
    apply_attrib(vao, index);
}
void vertex_array_attrib_binding(GLuint vao, GLuint index, GLuint binding) {
    vertex_arrays[vao].attribs[index].binding = binding;
    apply_attrib(vao, index);
}

void clip_control(GLenum origin, GLenum depth) {
    if (!found.clip_control) {
        if (depth == GL_ZERO_TO_ONE) unsupported("glClipControl (EXT_clip_control)");
        return;  // the default, -1..1
    }
    impossible_clip_control(static_cast<int>(origin), static_cast<int>(depth));
}
void color_mask_i(GLuint index, GLboolean r, GLboolean g, GLboolean b, GLboolean a) {
    if (!found.draw_buffers_indexed) unsupported("glColorMaski (OES_draw_buffers_indexed)");
    impossible_color_mask_i(static_cast<int>(index), r, g, b, a);
}
void get_query_object_ui64v(GLuint query, GLenum name, GLuint64* value) {
    GLuint v = 0;
    glGetQueryObjectuiv(query, name, &v);
    *value = v;
}

void unsupported(const char* call) {
    std::fprintf(stderr, "impossible: internal error: %s is not available in WebGL 2\n", call);
    std::abort();
}

}  // namespace impossible::gl::webgl

#endif  // __EMSCRIPTEN__
