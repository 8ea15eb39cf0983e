// z-clear portals (--technique z-clear), the PowerVR scheme, for comparison
// with the stencil recursion: for each visible door of the head's room, its
// target room is drawn first, within the door's rectangle on screen and
// clipped at the target portal's plane; then depth is cleared, the doors are
// drawn into depth and the head's room last, whose surfaces behind a door
// fail the depth test and leave the target room showing there. No stencil
// marks a door's pixels: where one door's rectangle overlaps another door on
// screen, the door drawn later shows its room there (docs/cli.md).
//
// The stencil stays 0: each target is drawn as the root level of a frame one
// level shallower, so that its doors show the fill.
#include <algorithm>
#include <cassert>
#include <string>

#include "render/objects/object_culling.hpp"
#include "render/portals/portal_draw.hpp"
#include "render/portals/portal_recursion.hpp"
#include "render/portals/technique_zclear.hpp"

namespace impossible::render {
namespace {

// Which part of each eye's image may show each door of the head's room: as
// portal_recursion.cpp's visible_portals for a level-0 view (no exit).
std::vector<std::array<NdcRect, 2>> zclear_visible_doors(const DrawContext& ctx, const LevelView& view,
                                                         const std::vector<int>& portals) {
    const SceneData& r = ctx.scene;
    const FrameDesc& f = ctx.frame;
    std::vector<std::array<NdcRect, 2>> visible(portals.size());
    for (size_t k = 0; k < portals.size(); ++k) {
        const math::PortalRect& rect = r.portals[portals[k]].rect;
        for (int e = 0; e < 2; ++e) {
            const EyeView& ev = view.eyes[e];
            visible[k][e] = NdcRect::none();
            if (!ev.active) continue;
            const NdcRect seen = portal_rect(rect, ev);
            if (covers_pixel_centre(seen, f.eye_width, f.eye_height, f.samples) &&
                !(f.cull_objects && hidden_by_occluder(r.objects[static_cast<size_t>(view.cell)], ev, rect)))
                visible[k][e] = seen;
        }
    }
    return visible;
}

// Depth back to far within `scissor` (everywhere without one).
void zclear_depth(const DrawContext& ctx, const Scissor& scissor) {
    gl::StateCache& state = ctx.state;
    state.draw_framebuffer(ctx.target.framebuffer.get());
    state.apply(kClearState, 0);
    if (scissor)
        state.scissor(*scissor);
    else
        state.no_scissor();
    const GLfloat far = far_depth(ctx.frame);
    glClearNamedFramebufferfv(ctx.target.framebuffer.get(), GL_DEPTH, 0, &far);
}

// Door `p`'s target room in each eye's rectangle of the door: drawn as the
// root level of a frame one level shallower (its doors show the fill), with
// the stencil at 0 everywhere. Its colour fragments are not profiled (a
// level-0 view's doors would nest in the door's own time).
void zclear_draw_target(const DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects) {
    for (int e = 0; e < 2; ++e) {
        std::array<NdcRect, 2> one = {NdcRect::none(), NdcRect::none()};
        one[e] = rects[e];
        if (view.eyes[e].active && !rects[e].empty()) zclear_depth(ctx, scissor_of(ctx, one, view));
    }
    FrameDesc shallower = ctx.frame;
    shallower.max_depth = ctx.frame.max_depth - 1;
    const DrawContext target_ctx{.state = ctx.state,
                                 .scene = ctx.scene,
                                 .programs = ctx.programs,
                                 .lights = ctx.lights,
                                 .frame = shallower,
                                 .scene_program = ctx.scene_program,
                                 .material_program = ctx.material_program,
                                 .target = ctx.target,
                                 .targets = ctx.targets,
                                 .projections = ctx.projections,
                                 .eye = ctx.eye,
                                 .profiler = nullptr,
                                 .scratch = ctx.scratch};
    LevelView target = child_view(ctx, view, p, rects);
    target.level = 0;
    if (ctx.profiler) ctx.profiler->begin_top_portal(p);
    ctx.scratch.stats.portal_passes_drawn += 1;
    draw_level(target_ctx, target);
    if (ctx.profiler) ctx.profiler->end_top_portal(ctx.scratch.stats);
    ctx.scratch.stats.max_level_reached = std::max(ctx.scratch.stats.max_level_reached, 1);
}

}  // namespace

Result<void> check_zclear(const SceneData& r, const FrameDesc& frame) {
    // Settings are named as {field}, for each front end to spell
    // (session/field_error.hpp): the command line as its flags.
    const std::string refused = "{technique} z-clear ";
    if (frame.max_depth > 1)
        return Error{refused + "draws one level of doors: {max_depth} " + std::to_string(frame.max_depth) +
                     " (give {max_depth} 1)"};
    for (const scene::PortalInfo& p : r.portals)
        if (p.kind != layout::PortalKind::Door)
            return Error{refused + "draws doors only: the layout has a " +
                         (p.kind == layout::PortalKind::Mirror ? "mirror" : "window")};
    if (r.has_volumes) return Error{refused + "draws doors only: the layout has volumes"};
    if (!frame.cull_portals) return Error{refused + "needs each door's rectangle: not with {no_cull}"};
    if (frame.portal_texture_scale > 0.0) return Error{refused + "and portal textures exclude each other"};
    return {};
}

void draw_zclear(const DrawContext& ctx, const LevelView& view) {
    if (ctx.frame.max_depth < 1) {  // every door shows the fill: nothing to reorder
        draw_level(ctx, view);
        return;
    }
    FrameStats& stats = ctx.scratch.stats;
    const std::vector<int>& portals = ctx.scene.links.room_portals[view.cell];
    const std::vector<std::array<NdcRect, 2>> visible = zclear_visible_doors(ctx, view, portals);
    std::vector<size_t> fills;
    for (size_t k = 0; k < portals.size(); ++k) {
        if (visible[k][0].empty() && visible[k][1].empty()) {
            stats.portal_passes_culled += 1;
        } else if (stats.portal_passes_drawn >= ctx.frame.max_portal_passes) {
            fills.push_back(k);
            stats.budget_fills += 1;
        } else {
            zclear_draw_target(ctx, view, portals[k], visible[k]);
        }
    }
    zclear_depth(ctx, std::nullopt);
    // The head's room over the targets, as a level's surfaces (its doors into
    // depth first; no stencil: the view's box bits are off, and the layout
    // has no volumes).
    draw_level_surfaces(ctx, view, portals, visible);
    for (size_t k : fills) draw_fill(ctx, view, portals[k], visible[k], 0);
}

}  // namespace impossible::render
