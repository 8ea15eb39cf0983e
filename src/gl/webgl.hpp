// The web build's GL (emscripten only): WebGL 2, which is OpenGL ES 3.0, with
// the GL 4.5 calls the renderer makes (direct state access, program
// uniforms, clip control) mapped onto ES calls that bind, act and restore.
// The renderer's sources stay as they are; what ES lacks entirely
// (multisampled textures, viewport arrays, conditional rendering, storage
// buffers) is refused before it is reached (render/web_profile.hpp and the
// view options), so these few are declared only to compile and fail loudly.
#pragma once

#include <GLES3/gl3.h>

#include <cstdint>

// Enums GL 4.5 has and ES 3.0 lacks: the values are GL's; the extensions
// that WebGL offers (EXT_clip_control, WEBGL_clip_cull_distance) use the same.
#define GL_LOWER_LEFT 0x8CA1
#define GL_NEGATIVE_ONE_TO_ONE 0x935E
#define GL_ZERO_TO_ONE 0x935F
#define GL_CLIP_DISTANCE0 0x3000
#define GL_DRAW_INDIRECT_BUFFER 0x8F3F
#define GL_SHADER_STORAGE_BUFFER 0x90D2
#define GL_SAMPLES_PASSED 0x8914
#define GL_TEXTURE_2D_MULTISAMPLE 0x9100
#define GL_TEXTURE_CUBE_MAP_ARRAY 0x9009
#define GL_QUERY_WAIT 0x8E13
#define GL_DYNAMIC_STORAGE_BIT 0x0100
#define GL_SAMPLE_POSITION 0x8E50
#define GL_DEPTH_COMPONENT32 0x81A7
#define GL_TEXTURE_CUBE_MAP_SEAMLESS 0x884F
#define GL_STACK_OVERFLOW 0x0503
#define GL_CLAMP_TO_BORDER 0x812D
#define GL_TEXTURE_BORDER_COLOR 0x1004
#define GL_MAX_INTEGER_SAMPLES 0x9110

using GLuint64 = std::uint64_t;

namespace impossible::gl::webgl {

// Which of WebGL's extensions the context has (read once it is made).
struct Extensions {
    bool clip_distance = false;         // WEBGL_clip_cull_distance
    bool clip_control = false;          // EXT_clip_control
    bool draw_buffers_indexed = false;  // OES_draw_buffers_indexed
    bool float_blend = false;
};
const Extensions& extensions();
void read_extensions();

// Binding trackers: the compatibility calls bind objects to act on them and
// put back what was bound, which they know from these.
void use_program(GLuint program);
void enable(GLenum cap);
void disable(GLenum cap);
void bind_vertex_array(GLuint vao);
void bind_framebuffer(GLenum target, GLuint framebuffer);
void bind_buffer(GLenum target, GLuint buffer);
void active_texture(GLenum unit);
void bind_texture(GLenum target, GLuint texture);

void create_buffers(GLsizei n, GLuint* names);
void create_vertex_arrays(GLsizei n, GLuint* names);
void create_textures(GLenum target, GLsizei n, GLuint* names);
void create_renderbuffers(GLsizei n, GLuint* names);
void create_framebuffers(GLsizei n, GLuint* names);
void create_queries(GLenum target, GLsizei n, GLuint* names);
void delete_buffers(GLsizei n, const GLuint* names);
void delete_textures(GLsizei n, const GLuint* names);
void delete_vertex_arrays(GLsizei n, const GLuint* names);

void named_buffer_storage(GLuint buffer, GLsizeiptr size, const void* data, GLbitfield flags);
void named_buffer_data(GLuint buffer, GLsizeiptr size, const void* data, GLenum usage);
void named_buffer_sub_data(GLuint buffer, GLintptr offset, GLsizeiptr size, const void* data);

void texture_storage_2d(GLuint texture, GLsizei levels, GLenum format, GLsizei width, GLsizei height);
void texture_storage_3d(GLuint texture, GLsizei levels, GLenum format, GLsizei width, GLsizei height, GLsizei depth);
void texture_storage_2d_multisample(GLuint texture, GLsizei samples, GLenum format, GLsizei width, GLsizei height,
                                    GLboolean fixed);
void texture_sub_image_2d(GLuint texture, GLint level, GLint x, GLint y, GLsizei width, GLsizei height, GLenum format,
                          GLenum type, const void* pixels);
void texture_parameter_i(GLuint texture, GLenum name, GLint value);
void texture_parameter_fv(GLuint texture, GLenum name, const GLfloat* value);
void generate_texture_mipmap(GLuint texture);
void bind_texture_unit(GLuint unit, GLuint texture);

void named_renderbuffer_storage(GLuint renderbuffer, GLenum format, GLsizei width, GLsizei height);
void named_renderbuffer_storage_multisample(GLuint renderbuffer, GLsizei samples, GLenum format, GLsizei width,
                                            GLsizei height);

void named_framebuffer_texture(GLuint framebuffer, GLenum attachment, GLuint texture, GLint level);
void named_framebuffer_texture_layer(GLuint framebuffer, GLenum attachment, GLuint texture, GLint level, GLint layer);
void named_framebuffer_renderbuffer(GLuint framebuffer, GLenum attachment, GLenum target, GLuint renderbuffer);
void named_framebuffer_draw_buffer(GLuint framebuffer, GLenum buffer);
void named_framebuffer_draw_buffers(GLuint framebuffer, GLsizei n, const GLenum* buffers);
void named_framebuffer_read_buffer(GLuint framebuffer, GLenum buffer);
GLenum check_named_framebuffer_status(GLuint framebuffer, GLenum target);
void clear_named_framebuffer_fv(GLuint framebuffer, GLenum buffer, GLint drawbuffer, const GLfloat* value);
void clear_named_framebuffer_uiv(GLuint framebuffer, GLenum buffer, GLint drawbuffer, const GLuint* value);
void clear_named_framebuffer_fi(GLuint framebuffer, GLenum buffer, GLint drawbuffer, GLfloat depth, GLint stencil);
void blit_named_framebuffer(GLuint from, GLuint to, GLint x0, GLint y0, GLint x1, GLint y1, GLint u0, GLint v0,
                            GLint u1, GLint v1, GLbitfield mask, GLenum filter);

void vertex_array_vertex_buffer(GLuint vao, GLuint binding, GLuint buffer, GLintptr offset, GLsizei stride);
void vertex_array_element_buffer(GLuint vao, GLuint buffer);
void enable_vertex_array_attrib(GLuint vao, GLuint index);
void vertex_array_attrib_format(GLuint vao, GLuint index, GLint size, GLenum type, GLboolean normalized, GLuint offset);
void vertex_array_attrib_binding(GLuint vao, GLuint index, GLuint binding);

// Storage buffers become uniform buffers of at most kUniformBufferBytes
// (the shaders' WEBGL branches declare them so); every buffer store is at
// least that big, since WebGL refuses a draw whose bound block is larger
// than its buffer.
inline constexpr GLsizeiptr kUniformBufferBytes = 16384;
void bind_buffer_base(GLenum target, GLuint index, GLuint buffer);
// glCopyImageSubData of one 2D level, as a blit (scissor off).
void copy_image_sub_data(GLuint from, GLenum from_target, GLint from_level, GLint x, GLint y, GLint z, GLuint to,
                         GLenum to_target, GLint to_level, GLint u, GLint v, GLint w, GLsizei width, GLsizei height,
                         GLsizei depth);

void clip_control(GLenum origin, GLenum depth);
void color_mask_i(GLuint index, GLboolean r, GLboolean g, GLboolean b, GLboolean a);
void get_query_object_ui64v(GLuint query, GLenum name, GLuint64* value);

// What WebGL cannot do at all: each reports the call and aborts (the web
// profile refuses the options that would reach them).
[[noreturn]] void unsupported(const char* call);

// The program in use (webgl.cpp's record of it).
GLuint current_program();

template <typename T>
void program_uniform(GLuint program, T&& set) {
    const GLuint was = current_program();
    if (was != program) use_program(program);
    set();
    if (was != program) use_program(was);
}

}  // namespace impossible::gl::webgl

#define IMPOSSIBLE_WEBGL_UNIFORM(program, call) ::impossible::gl::webgl::program_uniform(program, [&] { call; })
#define glProgramUniform1i(p, l, a) IMPOSSIBLE_WEBGL_UNIFORM(p, glUniform1i(l, a))
#define glProgramUniform1ui(p, l, a) IMPOSSIBLE_WEBGL_UNIFORM(p, glUniform1ui(l, a))
#define glProgramUniform1f(p, l, a) IMPOSSIBLE_WEBGL_UNIFORM(p, glUniform1f(l, a))
#define glProgramUniform2f(p, l, a, b) IMPOSSIBLE_WEBGL_UNIFORM(p, glUniform2f(l, a, b))
#define glProgramUniform3f(p, l, a, b, c) IMPOSSIBLE_WEBGL_UNIFORM(p, glUniform3f(l, a, b, c))
#define glProgramUniform4f(p, l, a, b, c, d) IMPOSSIBLE_WEBGL_UNIFORM(p, glUniform4f(l, a, b, c, d))
#define glProgramUniform3fv(p, l, n, v) IMPOSSIBLE_WEBGL_UNIFORM(p, glUniform3fv(l, n, v))
#define glProgramUniform4fv(p, l, n, v) IMPOSSIBLE_WEBGL_UNIFORM(p, glUniform4fv(l, n, v))
#define glProgramUniformMatrix3fv(p, l, n, t, v) IMPOSSIBLE_WEBGL_UNIFORM(p, glUniformMatrix3fv(l, n, t, v))
#define glProgramUniformMatrix4fv(p, l, n, t, v) IMPOSSIBLE_WEBGL_UNIFORM(p, glUniformMatrix4fv(l, n, t, v))

#define glUseProgram ::impossible::gl::webgl::use_program
#define glEnable ::impossible::gl::webgl::enable
#define glDisable ::impossible::gl::webgl::disable
#define glBindVertexArray ::impossible::gl::webgl::bind_vertex_array
#define glBindFramebuffer ::impossible::gl::webgl::bind_framebuffer
#define glBindBuffer ::impossible::gl::webgl::bind_buffer
#define glActiveTexture ::impossible::gl::webgl::active_texture
#define glBindTexture ::impossible::gl::webgl::bind_texture
#define glCreateBuffers ::impossible::gl::webgl::create_buffers
#define glCreateVertexArrays ::impossible::gl::webgl::create_vertex_arrays
#define glCreateTextures ::impossible::gl::webgl::create_textures
#define glCreateRenderbuffers ::impossible::gl::webgl::create_renderbuffers
#define glCreateFramebuffers ::impossible::gl::webgl::create_framebuffers
#define glCreateQueries ::impossible::gl::webgl::create_queries
#define glDeleteBuffers ::impossible::gl::webgl::delete_buffers
#define glDeleteTextures ::impossible::gl::webgl::delete_textures
#define glDeleteVertexArrays ::impossible::gl::webgl::delete_vertex_arrays
#define glNamedBufferStorage ::impossible::gl::webgl::named_buffer_storage
#define glNamedBufferData ::impossible::gl::webgl::named_buffer_data
#define glNamedBufferSubData ::impossible::gl::webgl::named_buffer_sub_data
#define glTextureStorage2D ::impossible::gl::webgl::texture_storage_2d
#define glTextureStorage3D ::impossible::gl::webgl::texture_storage_3d
#define glTextureStorage2DMultisample ::impossible::gl::webgl::texture_storage_2d_multisample
#define glTextureSubImage2D ::impossible::gl::webgl::texture_sub_image_2d
#define glTextureParameteri ::impossible::gl::webgl::texture_parameter_i
#define glTextureParameterfv ::impossible::gl::webgl::texture_parameter_fv
#define glGenerateTextureMipmap ::impossible::gl::webgl::generate_texture_mipmap
#define glBindTextureUnit ::impossible::gl::webgl::bind_texture_unit
#define glNamedRenderbufferStorage ::impossible::gl::webgl::named_renderbuffer_storage
#define glNamedRenderbufferStorageMultisample ::impossible::gl::webgl::named_renderbuffer_storage_multisample
#define glNamedFramebufferTexture ::impossible::gl::webgl::named_framebuffer_texture
#define glNamedFramebufferTextureLayer ::impossible::gl::webgl::named_framebuffer_texture_layer
#define glNamedFramebufferRenderbuffer ::impossible::gl::webgl::named_framebuffer_renderbuffer
#define glNamedFramebufferDrawBuffer ::impossible::gl::webgl::named_framebuffer_draw_buffer
#define glNamedFramebufferDrawBuffers ::impossible::gl::webgl::named_framebuffer_draw_buffers
#define glNamedFramebufferReadBuffer ::impossible::gl::webgl::named_framebuffer_read_buffer
#define glCheckNamedFramebufferStatus ::impossible::gl::webgl::check_named_framebuffer_status
#define glClearNamedFramebufferfv ::impossible::gl::webgl::clear_named_framebuffer_fv
#define glClearNamedFramebufferuiv ::impossible::gl::webgl::clear_named_framebuffer_uiv
#define glClearNamedFramebufferfi ::impossible::gl::webgl::clear_named_framebuffer_fi
#define glBlitNamedFramebuffer ::impossible::gl::webgl::blit_named_framebuffer
#define glVertexArrayVertexBuffer ::impossible::gl::webgl::vertex_array_vertex_buffer
#define glVertexArrayElementBuffer ::impossible::gl::webgl::vertex_array_element_buffer
#define glEnableVertexArrayAttrib ::impossible::gl::webgl::enable_vertex_array_attrib
#define glVertexArrayAttribFormat ::impossible::gl::webgl::vertex_array_attrib_format
#define glVertexArrayAttribBinding ::impossible::gl::webgl::vertex_array_attrib_binding
#define glClipControl ::impossible::gl::webgl::clip_control
#define glColorMaski ::impossible::gl::webgl::color_mask_i
#define glGetQueryObjectui64v ::impossible::gl::webgl::get_query_object_ui64v
#define glViewportIndexedf(...) ::impossible::gl::webgl::unsupported("glViewportIndexedf")
#define glBeginConditionalRender(...) ::impossible::gl::webgl::unsupported("glBeginConditionalRender")
#define glEndConditionalRender(...) ::impossible::gl::webgl::unsupported("glEndConditionalRender")
#define glCopyImageSubData ::impossible::gl::webgl::copy_image_sub_data
#define glBindBufferBase ::impossible::gl::webgl::bind_buffer_base
#define glGetMultisamplefv(...) ::impossible::gl::webgl::unsupported("glGetMultisamplefv")
#define glMultiDrawElementsIndirect(...) ::impossible::gl::webgl::unsupported("glMultiDrawElementsIndirect")
