#include "preview/overlay.hpp"

#include <cstddef>

#include "render/programs/scene_program.hpp"

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

Result<OverlayProgram> build_overlay_program() {
    OverlayProgram out;
    Result<gl::Program> built =
        gl::build_program({render::embedded_shader(GL_VERTEX_SHADER, "shaders/preview_overlay.vert.glsl"),
                           render::embedded_shader(GL_FRAGMENT_SHADER, "shaders/preview_overlay.frag.glsl")},
                          "");
    if (!built) return built;
    out.program = std::move(*built);
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

void draw_overlay(OverlayProgram& p, gl::StateCache& state, const OverlayBatch& batch, GLuint color_mask) {
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
    state.apply(gl::plain_2d_state(true, color_mask), 0);
    state.no_scissor();
    state.program(p.program.get());
    state.vertex_array(p.vao.get());
    if (!batch.triangles.empty()) glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(batch.triangles.size()));
    if (!batch.lines.empty())
        glDrawArrays(GL_LINES, static_cast<GLint>(batch.triangles.size()), static_cast<GLsizei>(batch.lines.size()));
    state.vertex_array(0);
    state.program(0);
}

}  // namespace impossible::preview
