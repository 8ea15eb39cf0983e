// Internal to src/render: recursive stencil portals inside the single
// instanced stereo pass, and the drawing helpers shared by the stencil
// portals (portal_recursion.cpp) and render-to-texture portals
// (portal_texture.cpp).
#pragma once

#include <array>

#include "render/frame_profiler.hpp"
#include "render/passes.hpp"
#include "render/renderer_data.hpp"
#include "render/view.hpp"

namespace impossible::render {

struct DrawContext {
    RendererData& renderer;
    const SceneProgram& program;
    const FrameDesc& frame;
    FrameStats& stats;
    math::dmat4 projection{1.0};
    FrameProfiler* profiler = nullptr;  // null unless FrameDesc::profile
    size_t mark_queries_used = 0;       // of RendererData::mark_queries, this frame
    bool conditional = false;           // inside a portal's conditional rendering
};

// Draws `view` where the stencil equals view.level, then every portal of its
// cell that either eye can see, recursively.
void draw_level(DrawContext& ctx, const LevelView& view);

// --- Shared by the stencil and the render-to-texture portals (portal_draw.cpp).

// The pass's state, for the frame's depth mode, with the stencil reference.
void use_pass(DrawContext& ctx, Pass pass, int stencil_ref);

// The pixel rectangle (GL window coordinates) covering both eyes' rects.
gl::ScissorRect scissor_of(const DrawContext& ctx, const std::array<NdcRect, 2>& rects, const LevelView& view);

// Uploads the per-eye uniforms of a draw: matrices, rectangles, planes.
void set_eye_uniforms(const DrawContext& ctx, const LevelView& view, const std::array<NdcRect, 2>& rects);

// One instanced draw (one per eye in two-pass stereo) of an index range.
void draw_range(DrawContext& ctx, const scene::IndexRange& range);

// Draws a portal's box for the eyes with a non-empty rect: the front face for
// eyes in front of it, the inner faces for eyes in its column.
void draw_portal_box(DrawContext& ctx, const LevelView& view, int portal, const std::array<NdcRect, 2>& rects);

// The view through `portal` (of view.cell) into its target's room.
LevelView child_view(const DrawContext& ctx, const LevelView& view, int portal, const std::array<NdcRect, 2>& rects);

// --- Render-to-texture portals (portal_texture.cpp).

// Makes sure there is one sampled target per portal of the frame's room, of
// FrameDesc::portal_texture_scale × the eye size; an incomplete one is an
// error.
Result<void> ensure_portal_textures(RendererData& r, const FrameDesc& frame);

// The view through portal `p` of the head's cell drawn into portal texture
// `slot`, which the box then shows where it is the visible surface.
void draw_portal_via_texture(DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects,
                             size_t slot);

}  // namespace impossible::render
