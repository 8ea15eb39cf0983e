// Overlays of the preview window (HUD, minimap, boundary grid): coloured
// triangles and lines collected on the CPU, drawn with one small program.
//
// The renderer keeps GL state in a StateCache and enables the clip distances
// and reversed-Z clip control globally; OverlayGlState saves what overlays
// change, sets plain 2D state, and restores it, so the renderer's cache stays
// true (cmd_preview also calls renderer.state.invalidate() after each frame).
#pragma once

#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "gl/handles.hpp"

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
OverlayProgram build_overlay_program(std::string& error);

// Draws the batch (triangles first, then lines) into the current viewport.
void draw_overlay(OverlayProgram& program, const OverlayBatch& batch);

// Saves the fixed-function state overlays touch, and sets: no depth, stencil,
// culling, scissor or clip distances; alpha blending; all colour channels.
struct OverlayGlState {
    OverlayGlState();
    ~OverlayGlState();
    OverlayGlState(const OverlayGlState&) = delete;
    OverlayGlState& operator=(const OverlayGlState&) = delete;

private:
    bool depth_, stencil_, cull_, scissor_, blend_, clip_[5];
    GLboolean color_mask_[4];
    GLint viewport_[4];
};

}  // namespace impossible::preview
