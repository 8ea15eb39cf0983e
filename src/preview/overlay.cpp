#include "preview/overlay.hpp"

#include <cstddef>

#include "render/scene_program.hpp"

namespace impossible::preview {

glm::vec4 OverlayBatch::clip_of(glm::vec2 p) const {
    return {2.0f * p.x / float(width) - 1.0f, 1.0f - 2.0f * p.y / float(height), 0.5f, 1.0f};
}

void OverlayBatch::rect(glm::vec2 a, glm::vec2 b, glm::vec4 color) {
    triangle(a, {b.x, a.y}, b, color);
    triangle(a, b, {a.x, b.y}, color);
}

void OverlayBatch::line(glm::vec2 a, glm::vec2 b, glm::vec4 color) {
    lines.push_back({clip_of(a), color});
    lines.push_back({clip_of(b), color});
}

void OverlayBatch::triangle(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec4 color) {
    triangles.push_back({clip_of(a), color});
    triangles.push_back({clip_of(b), color});
    triangles.push_back({clip_of(c), color});
}

void OverlayBatch::clip_line(glm::vec4 a, glm::vec4 b, glm::vec4 color) {
    lines.push_back({a, color});
    lines.push_back({b, color});
}

OverlayProgram build_overlay_program(std::string& error) {
    OverlayProgram out;
    gl::ProgramResult built = gl::build_program({render::embedded_shader(GL_VERTEX_SHADER, "shaders/preview_overlay.vert.glsl"),
                                                 render::embedded_shader(GL_FRAGMENT_SHADER, "shaders/preview_overlay.frag.glsl")},
                                                "");
    if (!built.error.empty()) {
        error = built.error;
        return out;
    }
    out.program = std::move(built.program);
    out.vao = gl::create_vertex_array();
    const GLuint vao = out.vao.get();
    glEnableVertexArrayAttrib(vao, 0);
    glEnableVertexArrayAttrib(vao, 1);
    glVertexArrayAttribFormat(vao, 0, 4, GL_FLOAT, GL_FALSE, offsetof(OverlayVertex, position));
    glVertexArrayAttribFormat(vao, 1, 4, GL_FLOAT, GL_FALSE, offsetof(OverlayVertex, color));
    glVertexArrayAttribBinding(vao, 0, 0);
    glVertexArrayAttribBinding(vao, 1, 0);
    return out;
}

void draw_overlay(OverlayProgram& p, const OverlayBatch& batch) {
    const std::size_t count = batch.triangles.size() + batch.lines.size();
    if (count == 0) return;
    if (count > p.capacity) {
        p.capacity = count * 2;
        p.buffer = gl::create_buffer();
        glNamedBufferStorage(p.buffer.get(), static_cast<GLsizeiptr>(p.capacity * sizeof(OverlayVertex)), nullptr,
                             GL_DYNAMIC_STORAGE_BIT);
        glVertexArrayVertexBuffer(p.vao.get(), 0, p.buffer.get(), 0, sizeof(OverlayVertex));
    }
    const GLsizeiptr tri_bytes = static_cast<GLsizeiptr>(batch.triangles.size() * sizeof(OverlayVertex));
    if (tri_bytes) glNamedBufferSubData(p.buffer.get(), 0, tri_bytes, batch.triangles.data());
    if (!batch.lines.empty())
        glNamedBufferSubData(p.buffer.get(), tri_bytes,
                             static_cast<GLsizeiptr>(batch.lines.size() * sizeof(OverlayVertex)), batch.lines.data());
    glUseProgram(p.program.get());
    glBindVertexArray(p.vao.get());
    if (!batch.triangles.empty()) glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(batch.triangles.size()));
    if (!batch.lines.empty())
        glDrawArrays(GL_LINES, static_cast<GLint>(batch.triangles.size()), static_cast<GLsizei>(batch.lines.size()));
    glBindVertexArray(0);
    glUseProgram(0);
}

OverlayGlState::OverlayGlState() {
    depth_ = glIsEnabled(GL_DEPTH_TEST);
    stencil_ = glIsEnabled(GL_STENCIL_TEST);
    cull_ = glIsEnabled(GL_CULL_FACE);
    scissor_ = glIsEnabled(GL_SCISSOR_TEST);
    blend_ = glIsEnabled(GL_BLEND);
    for (int i = 0; i < 5; ++i) clip_[i] = glIsEnabled(GL_CLIP_DISTANCE0 + i);
    glGetBooleanv(GL_COLOR_WRITEMASK, color_mask_);
    glGetIntegerv(GL_VIEWPORT, viewport_);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    for (int i = 0; i < 5; ++i) glDisable(GL_CLIP_DISTANCE0 + i);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

OverlayGlState::~OverlayGlState() {
    auto set = [](GLenum cap, bool on) { on ? glEnable(cap) : glDisable(cap); };
    set(GL_DEPTH_TEST, depth_);
    set(GL_STENCIL_TEST, stencil_);
    set(GL_CULL_FACE, cull_);
    set(GL_SCISSOR_TEST, scissor_);
    set(GL_BLEND, blend_);
    for (int i = 0; i < 5; ++i) set(GL_CLIP_DISTANCE0 + i, clip_[i]);
    glColorMask(color_mask_[0], color_mask_[1], color_mask_[2], color_mask_[3]);
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
}

}  // namespace impossible::preview
