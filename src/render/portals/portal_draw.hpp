// Internal to src/render: the drawing steps a portal level is made of
// (portal_draw.cpp), shared by the stencil portals (portal_recursion.hpp),
// mirrors and windows (portal_glass.hpp), render-to-texture portals
// (portal_texture.hpp) and z-clear portals (technique_zclear.hpp).
#pragma once

#include <array>

#include "render/draw/draw_state.hpp"
#include "render/portals/portal_steps.hpp"

namespace impossible::render {

// Stencil level → level + 1 where the portal is the visible surface, and
// depth there back to far; and every deeper level back to level with the
// portal's depth, so that it occludes the rest of the level (unless
// steps.unmark is off). Every kind of portal is drawn between these two.
void mark_portal(const DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects,
                 const PortalSteps& steps);
void unmark_portal(const DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects,
                   const PortalSteps& steps);

// Depth back to far where the stencil equals level `stencil_ref`, within
// the portal's rectangle in each eye that sees it: Pass::ClearDepth, or
// Pass::PortalMarkReset, which also marks (drawn with the portal's level).
void clear_depth_in_portal(const DrawContext& ctx, const LevelView& view, int stencil_ref,
                           const std::array<NdcRect, 2>& rects, Pass pass = Pass::ClearDepth);

// A level's cell: its plain batches as `draw` (with FrameDesc::multi_draw,
// in one call), and those with a texture or an alpha cutoff as `draw` with
// the material program, the batch's texture on kSceneTextureUnit. With
// culling on, only the props the level's eyes may see (object_culling.hpp).
void draw_cell(const DrawContext& ctx, const LevelView& view, const SceneDraw& draw);

// Draws a portal's box as `draw` for the eyes with a non-empty rect: the
// front face for eyes in front of it, the inner faces for eyes in its column.
void draw_portal_box(const DrawContext& ctx, const LevelView& view, const SceneDraw& draw, int portal,
                     const std::array<NdcRect, 2>& rects);

// The flat fill colour and id (shading::kPortalFillColor, kFillId) where the
// portal is the visible surface, in place of a view that is not drawn: at the
// recursion limit, past the frame's budget of portal passes, or a window's
// view through it cut by its weight. `stencil_ref` is the level of the pixels
// it covers (a window's are marked already). Counted as a portal fill.
void draw_fill(const DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects,
               int stencil_ref);

// The view through `portal` (of view.cell, a door or a window) into its
// target's room, with the given share of the pixels.
LevelView child_view(const DrawContext& ctx, const LevelView& view, int portal, const std::array<NdcRect, 2>& rects,
                     double weight_factor = 1.0);

// The view reflected in `portal` (of view.cell, a mirror or a window): the
// same cell from the eyes mirrored in its plane, clipped at it.
LevelView reflected_view(const DrawContext& ctx, const LevelView& view, int portal, const std::array<NdcRect, 2>& rects,
                         double weight_factor);

}  // namespace impossible::render
