// Overlays of the preview window (HUD, minimap, boundary grid): coloured
// triangles and lines collected on the CPU, drawn with one small program.
//
// All GL state goes through the window context's StateCache, which the
// renderer shares: overlays set their own state through it (no depth,
// stencil, culling, scissor or clip distances; alpha blending) and need not
// save or restore anything.
#pragma once

#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "base/result.hpp"
#include "gl/handles.hpp"
#include "gl/state.hpp"

namespace impossible::preview {

struct OverlayVertex {
    glm::vec4 position;  // clip space
    glm::vec4 color;     // straight alpha
};

// Geometry for one viewport. Pixel coordinates have their origin at the top
// left of a viewport of `width` × `height` pixels.
struct OverlayBatch {
    int width = 1, height = 1;
    std::vector<OverlayVertex> triangles;
    std::vector<OverlayVertex> lines;

    glm::vec4 clip_of(glm::vec2 pixel) const;
    void rect(glm::vec2 min, glm::vec2 max, glm::vec4 color);
    void line(glm::vec2 a, glm::vec2 b, glm::vec4 color);
    void triangle(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec4 color);
    void clip_line(glm::vec4 a, glm::vec4 b, glm::vec4 color);
    bool empty() const { return triangles.empty() && lines.empty(); }
};

struct OverlayProgram {
    gl::Program program;
    gl::VertexArray vao;
    gl::Buffer buffer;
    std::size_t capacity = 0;  // vertices the buffer holds
};

// Needs a current GL 4.5 context; `error` names the failing shader.
Result<OverlayProgram> build_overlay_program();

// Draws the batch (triangles first, then lines) into the current framebuffer
// and viewport, alpha-blended, writing the given colour channels.
void draw_overlay(OverlayProgram& program, gl::StateCache& state, const OverlayBatch& batch,
                  GLuint color_mask = gl::kColorAll);

}  // namespace impossible::preview
