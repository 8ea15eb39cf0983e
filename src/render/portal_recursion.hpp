// Recursive stencil portals inside the single instanced stereo pass.
#pragma once

#include "render/renderer.hpp"
#include "render/view.hpp"

namespace impossible::render {

// Per-frame measurements when FrameDesc::profile is set: one occlusion query
// per colour draw, tagged with the level-0 portal whose subtree it belongs to
// (-1: the head's own cell).
struct FrameProfiler {
    struct ColourQuery {
        GLuint query = 0;
        int top_portal = -1;
    };
    std::vector<ColourQuery> queries;
    int top_portal = -1;
};

struct DrawContext {
    Renderer& renderer;
    const SceneProgram& program;
    const FrameDesc& frame;
    FrameStats& stats;
    math::dmat4 projection{1.0};
    FrameProfiler* profiler = nullptr;  // null unless FrameDesc::profile
    size_t mark_queries_used = 0;       // of Renderer::mark_queries, this frame
    bool conditional = false;           // inside a portal's conditional rendering
};

// Reads back and deletes the profiler's queries into stats (colour_fragments,
// the portal_costs' fragments).
void collect_profile(FrameProfiler& profiler, FrameStats& stats);

// Draws `view` where the stencil equals view.level, then every portal of its
// cell that either eye can see, recursively.
void draw_level(DrawContext& ctx, const LevelView& view);

}  // namespace impossible::render
