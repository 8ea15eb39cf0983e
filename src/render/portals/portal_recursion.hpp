// Internal to src/render: recursive stencil portals inside the single
// instanced stereo pass, and the drawing steps shared by the stencil portals
// (portal_recursion.cpp), mirrors and windows (portal_glass.cpp) and
// render-to-texture portals (portal_texture.cpp).
#pragma once

#include <array>
#include <vector>

#include "render/draw/draw_state.hpp"

namespace impossible::render {

// Draws `view` where the stencil equals view.level, then every portal of its
// cell that either eye can see, recursively.
void draw_level(const DrawContext& ctx, const LevelView& view);

// A level's portal boxes of `portals` visible in `visible` (per portal, the
// eyes' rectangles) into depth, then the cell's surfaces, its objects'
// instances and its volumes' rooms, before any portal is marked.
void draw_level_surfaces(const DrawContext& ctx, const LevelView& view, const std::vector<int>& portals,
                         const std::vector<std::array<NdcRect, 2>>& visible);

// --- Shared by the stencil and the render-to-texture portals (portal_draw.cpp).

// How a visible portal of a level is marked and unmarked (portal_steps.cpp).
struct PortalSteps {
    // One quad per eye marks the portal and resets its depth (the box bit,
    // passes.hpp): no other visible portal of the level comes near it on
    // screen. Else its box marks and a quad resets depth, two draws.
    bool one_draw_mark = false;
    // Unmarked after its view: some later portal of the level comes near it
    // on screen (or no culling). Else its pixels keep their deeper levels,
    // which no later draw of the level touches, until an unmark of an outer
    // level or the end of the frame.
    bool unmark = true;
};

// The steps of each portal of the level with a non-empty rectangle in
// `visible` (one per portal of view.cell).
std::vector<PortalSteps> portal_steps(const DrawContext& ctx, const LevelView& view,
                                      const std::vector<std::array<NdcRect, 2>>& visible);

// Stencil level → level + 1 where the portal is the visible surface, and
// depth there back to far; and every deeper level back to level with the
// portal's depth, so that it occludes the rest of the level (unless
// steps.unmark is off). Every kind of portal is drawn between these two.
void mark_portal(const DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects,
                 const PortalSteps& steps);
void unmark_portal(const DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects,
                   const PortalSteps& steps);

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

// --- Mirrors and windows (portal_glass.cpp).

// A visible mirror or window of `view` below the recursion limit: the view(s)
// in it, tinted and blended, drawn where it is the visible surface.
void draw_mirror_portal(const DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects,
                        const PortalSteps& steps);
void draw_window_portal(const DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects,
                        const PortalSteps& steps);

// The window blend's program for single-sample or multisampled targets,
// built on first use; prepare_frame makes the ones a frame may need.
Result<void> prepare_window_blend(Programs& programs, bool multisample);

// --- Shared steps of portal_recursion.cpp.

// Depth back to far where the stencil equals level `stencil_ref`, within
// the portal's rectangle in each eye that sees it: Pass::ClearDepth, or
// Pass::PortalMarkReset, which also marks (drawn with the portal's level).
void clear_depth_in_portal(const DrawContext& ctx, const LevelView& view, int stencil_ref,
                           const std::array<NdcRect, 2>& rects, Pass pass = Pass::ClearDepth);

// --- Render-to-texture portals (portal_texture.cpp).

// Makes sure there is one sampled target per portal of the frame's room, of
// FrameDesc::portal_texture_scale × the eye size; an incomplete one is an
// error.
Result<void> ensure_portal_textures(const RendererData& r, FrameTargets& targets, const FrameDesc& frame);

// The view through portal `p` of the head's cell drawn into portal texture
// `slot`, which the box then shows where it is the visible surface.
void draw_portal_via_texture(const DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects,
                             size_t slot);

// --- z-clear portals (technique_zclear.cpp).

// Whether the frame's z-clear portals can be drawn (FrameDesc::z_clear):
// depth <= 1, doors only, no volumes, with culling, no portal textures; the
// error names the option and what breaks the rule.
Result<void> check_zclear(const RendererData& r, const FrameDesc& frame);

// The head's view (level 0) by the z-clear scheme: each visible door's target
// room first, within its rectangle, then depth cleared, the doors into depth
// and the head's room over them.
void draw_zclear(const DrawContext& ctx, const LevelView& view);

// --- Dynamic objects and volume portals (object_draw.cpp).

// The frame's dynamic objects placed (walk::place_objects), grouped per cell
// with their bounds and a culling tree per cell.
// `walks` (may be null) walks the moving props on from the last frame.
void place_frame_objects(const RendererData& r, const FrameDesc& frame, FrameObjects& out, walk::PropWalks* walks);

// The program a draw of `cell` uses: the plain or material one, or the
// variant with `flags` (and kVolumes where the cell has volumes).
const SceneProgram& cell_program(const DrawContext& ctx, int cell, unsigned flags = 0u);

// kLights under "lighting": "lights", else 0: what the colour passes add to
// their program's flags.
unsigned light_flags(const DrawContext& ctx);

// A colour pass's light uniforms for surfaces of `room` (the identity into
// the room's coordinates: the room's own vertices), counting the room's
// images in FrameStats::light_images when `count` is set. Nothing for a
// fixed layout.
void set_room_lights(const DrawContext& ctx, const SceneProgram& program, int room, bool count);

// The instances placed in `cell` that the level's eyes may see, drawn in
// `view` (whose cell is `cell`, or holds a volume whose target is `cell`)
// with id cell + 1; `inside` as set_volume_uniforms's.
void draw_cell_instances(const DrawContext& ctx, const LevelView& view, const Scissor& scissor, int cell, int inside);

// Each volume of view.cell: its target room's batches and instances, shown
// only inside the volume, tinted.
void draw_volume_rooms(const DrawContext& ctx, const LevelView& view, const Scissor& scissor);

}  // namespace impossible::render
