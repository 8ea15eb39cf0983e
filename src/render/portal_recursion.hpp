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
    const Target* target = nullptr;     // what is drawn into (its colour is copied for windows)
    size_t saved_colours_used = 0;      // of RendererData::saved_colours, by windows being drawn
    bool conditional = false;           // inside a portal's conditional rendering
    const SceneProgram* material_program = nullptr;  // `program` with materials; set when the scene has them
};

// Draws `view` where the stencil equals view.level, then every portal of its
// cell that either eye can see, recursively.
void draw_level(DrawContext& ctx, const LevelView& view);

// --- Shared by the stencil and the render-to-texture portals (portal_draw.cpp).

// The pass's state, for the frame's depth mode and the view's winding, with
// the stencil reference.
void use_pass(DrawContext& ctx, const LevelView& view, Pass pass, int stencil_ref);

// The pixel rectangle (GL window coordinates) covering both eyes' rects.
gl::ScissorRect scissor_of(const DrawContext& ctx, const std::array<NdcRect, 2>& rects, const LevelView& view);

// Uploads the per-eye uniforms of a draw: matrices, rectangles, planes.
void set_eye_uniforms(const DrawContext& ctx, const LevelView& view, const std::array<NdcRect, 2>& rects);

// The scissor of the portal's rects, when culling is on.
void limit_to_portal(DrawContext& ctx, const LevelView& view, const std::array<NdcRect, 2>& rects);

// Stencil level → level + 1 where the portal is the visible surface, and
// depth there back to far; and back to level with the portal's depth, so
// that it occludes the rest of the level. Every kind of portal is drawn
// between these two.
void mark_portal(DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects);
void unmark_portal(DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects);

// One instanced draw (one per eye in two-pass stereo) of an index range.
void draw_range(DrawContext& ctx, const scene::IndexRange& range);

// A level's cell: draw_range for each of its batches, with the batch's
// texture and alpha cutoff set (and unset after) where it has them. With
// culling on, only the props the level's eyes may see (object_culling.hpp).
void draw_cell(DrawContext& ctx, const LevelView& view);

// Draws a portal's box for the eyes with a non-empty rect: the front face for
// eyes in front of it, the inner faces for eyes in its column.
void draw_portal_box(DrawContext& ctx, const LevelView& view, int portal, const std::array<NdcRect, 2>& rects);

// The flat fill colour and id (shading::kPortalFillColor, kFillId) where the
// portal is the visible surface, in place of a view that is not drawn: at the
// recursion limit, past the frame's budget of portal passes, or a window's
// view through it cut by its weight. `stencil_ref` is the level of the pixels
// it covers (a window's are marked already). Counted as a portal fill.
void draw_fill(DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects, int stencil_ref);

// The view through `portal` (of view.cell, a door or a window) into its
// target's room, with the given share of the pixels.
LevelView child_view(const DrawContext& ctx, const LevelView& view, int portal, const std::array<NdcRect, 2>& rects,
                     double weight_factor = 1.0);

// The view reflected in `portal` (of view.cell, a mirror or a window): the
// same cell from the eyes mirrored in its plane, clipped at it.
LevelView reflected_view(const DrawContext& ctx, const LevelView& view, int portal,
                         const std::array<NdcRect, 2>& rects, double weight_factor);

// --- Mirrors and windows (portal_glass.cpp).

// A visible mirror or window of `view` below the recursion limit: the view(s)
// through it, tinted and blended, drawn where it is the visible surface.
void draw_mirror(DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects);
void draw_window(DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects);

// The window blend's program for single-sample or multisampled targets,
// built on first use; prepare_frame makes the ones a frame may need.
Result<void> prepare_window_blend(RendererData& r, bool multisample);

// --- Shared steps of portal_recursion.cpp.

// Depth back to far where the stencil equals stencil_ref, within the
// portal's rectangle in each eye that sees it.
void clear_depth_in_portal(DrawContext& ctx, const LevelView& view, int stencil_ref,
                           const std::array<NdcRect, 2>& rects);

// One full-target triangle with the bound program (the stencil limits it).
void draw_full_target(DrawContext& ctx);

void set_cell_id(const DrawContext& ctx, unsigned id, bool unshaded);

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
