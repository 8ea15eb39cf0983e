// Recursive stencil portals inside the single instanced stereo pass.
#pragma once

#include "render/renderer.hpp"
#include "render/view.hpp"

namespace impossible::render {

struct DrawContext {
    Renderer& renderer;
    const SceneProgram& program;
    const FrameDesc& frame;
    FrameStats& stats;
    math::dmat4 projection{1.0};
};

// Draws `view` where the stencil equals view.level, then every portal of its
// cell that either eye can see, recursively.
void draw_level(DrawContext& ctx, const LevelView& view);

}  // namespace impossible::render
