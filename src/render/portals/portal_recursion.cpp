// Recursive portal rendering with the stencil buffer, both eyes at once.
//
// The scheme is the classic stencil-portal recursion (as in e.g. Kilgard,
// "Improving Shadows and Reflections via the Stencil Buffer", NVIDIA 1999, and
// the portal renderers that followed): the stencil value of a pixel is the
// recursion level whose view it shows. Per portal: mark the pixels where its
// box is the visible surface (level → level + 1), reset depth there, draw the
// target room from the virtual cameras M_AB · eye clipped at the target
// portal's plane, recurse, then unmark and put the box's depth back so that
// it occludes what the rest of this level draws (where portals stand apart
// on screen, the mark and reset take one draw and the unmark none:
// portal_steps.cpp). Every draw is one instanced
// draw for both eyes; an eye that cannot see a portal gets an empty
// rectangle, which its clip distances turn into no work. Every draw names its
// pass, stencil reference, program and scissor (draw_state.hpp).
#include "render/portals/portal_recursion.hpp"

#include <algorithm>
#include <cassert>

#include "render/lights/light_draw.hpp"
#include "render/objects/object_draw.hpp"
#include "render/portals/portal_draw.hpp"
#include "render/portals/portal_glass.hpp"
#include "render/portals/portal_texture.hpp"

namespace impossible::render {

namespace {

// One visible portal of `view`: the fill at the depth limit, or mark, depth
// reset, the view through it (recursively) and unmark, as `steps` says.
void draw_portal(const DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects,
                 const PortalSteps& steps) {
    const int level = view.level;
    FrameStats& stats = ctx.scratch.stats;
    // The recursion limit, or the frame's budget of portal passes spent:
    // the portal shows the fill colour.
    const bool over_budget = stats.portal_passes_drawn >= ctx.frame.max_portal_passes;
    if (level >= ctx.frame.max_depth || over_budget) {
        draw_fill(ctx, view, p, rects, level);
        if (over_budget && level < ctx.frame.max_depth) stats.budget_fills += 1;
        return;
    }
    switch (ctx.scene.portals[p].kind) {
        case layout::PortalKind::Mirror: draw_mirror_portal(ctx, view, p, rects, steps); return;
        case layout::PortalKind::Window: draw_window_portal(ctx, view, p, rects, steps); return;
        case layout::PortalKind::Door: break;
    }
    mark_portal(ctx, view, p, rects, steps);
    stats.portal_passes_drawn += 1;
    draw_level(ctx, child_view(ctx, view, p, rects));
    unmark_portal(ctx, view, p, rects, steps);
}

// One occlusion query per visible portal of this level, drawn after the
// cell's surfaces: whether any pixel of the box is visible. Zero for every
// portal that does not pass (no query there).
std::vector<GLuint> test_portal_visibility(const DrawContext& ctx, const LevelView& view,
                                           const std::vector<int>& portals,
                                           const std::vector<std::array<NdcRect, 2>>& visible) {
    FrameScratch& s = ctx.scratch;
    std::vector<GLuint> queries(portals.size(), 0);
    const SceneDraw draw{Pass::PortalTest, view.level, &cell_program(ctx, view), level_scissor(ctx, view)};
    for (size_t k = 0; k < portals.size(); ++k) {
        if (visible[k][0].empty() && visible[k][1].empty()) continue;
        if (s.mark_queries_used == s.mark_queries.size())
            s.mark_queries.push_back(gl::create_query(GL_ANY_SAMPLES_PASSED));
        queries[k] = s.mark_queries[s.mark_queries_used++].get();
        glBeginQuery(GL_ANY_SAMPLES_PASSED, queries[k]);
        draw_portal_box(ctx, view, draw, portals[k], visible[k]);
        glEndQuery(GL_ANY_SAMPLES_PASSED);
    }
    return queries;
}

// draw_portal for a portal of the head's cell, timed by the profiler.
void draw_top_portal_profiled(const DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects,
                              const PortalSteps& steps) {
    ctx.profiler->begin_top_portal(p);
    draw_portal(ctx, view, p, rects, steps);
    ctx.profiler->end_top_portal(ctx.scratch.stats);
}

// Which part of each eye's image may show each portal of the view's cell:
// none where the pixel rule (docs/bounded-work.md) finds that the portal
// covers no pixel centre of the eye's rectangle, or, with culling, where a
// box prop hides it. Without culling (--no-cull) the rule still decides
// which portals are drawn, so that the frame makes the same passes; only
// the draws are not narrowed (set_eye_uniforms, level_scissor). The portal
// the view came out of lies behind a virtual eye that stands behind it,
// where the plane clips it.
// A headset's hidden area (hidden_mask.hpp) hides a portal from an eye
// whose rectangle of it holds no visible pixel; `masked[k]` is set when that
// alone hides portal k from an eye.
std::vector<std::array<NdcRect, 2>> visible_portals(const DrawContext& ctx, const LevelView& view,
                                                    const std::vector<int>& portals, std::vector<char>& masked) {
    const SceneData& r = ctx.scene;
    const FrameDesc& f = ctx.frame;
    const bool occluders = f.cull_portals && f.cull_objects;
    std::vector<std::array<NdcRect, 2>> visible(portals.size());
    masked.assign(portals.size(), 0);
    for (size_t k = 0; k < portals.size(); ++k) {
        const int p = portals[k];
        for (int e = 0; e < 2; ++e) {
            const EyeView& ev = view.eyes[e];
            const bool behind_exit = p == view.entered_by && ev.behind_exit;
            visible[k][e] = NdcRect::none();
            if (behind_exit || !ev.active) continue;
            const NdcRect rect = portal_rect(r.portals[p].rect, ev);
            if (!covers_pixel_centre(rect, f.eye_width, f.eye_height, f.samples)) continue;
            if (occluders && hidden_by_occluder(r.objects[static_cast<size_t>(view.cell)], ev, r.portals[p].rect))
                continue;
            if (!meets_visible_area(ctx.targets.hidden_mask, e, rect, f.samples)) {
                masked[k] = 1;
                continue;
            }
            visible[k][e] = rect;
        }
    }
    return visible;
}

}  // namespace

// The level's portal boxes into depth first, so that portals and surfaces
// occlude each other, and the cell's surfaces behind a portal fail the depth
// test instead of being drawn and then covered by the view through it; then
// the cell's surfaces, its dynamic objects' instances and its volumes' rooms,
// before any portal is marked so that they occlude it.
void draw_level_surfaces(const DrawContext& ctx, const LevelView& view, const std::vector<int>& portals,
                         const std::vector<std::array<NdcRect, 2>>& visible) {
    const int level = view.level;
    const Scissor scissor = level_scissor(ctx, view);
    const SceneProgram& program = cell_program(ctx, view);
    const SceneDraw depth{Pass::PortalDepth, level, &program, scissor};
    for (size_t k = 0; k < portals.size(); ++k)
        if (!visible[k][0].empty() || !visible[k][1].empty()) draw_portal_box(ctx, view, depth, portals[k], visible[k]);
    // The colour pass: under "lighting": "lights" the LIGHTS variant.
    const ColourQueryScope colour(ctx.profiler);
    draw_level_colour(ctx, view, scissor);
    draw_volume_rooms(ctx, view, scissor);
}

void draw_level(const DrawContext& ctx, const LevelView& view) {
    const SceneData& r = ctx.scene;
    FrameScratch& s = ctx.scratch;
    assert(view.cell >= 0 && static_cast<size_t>(view.cell) < r.cells.size());
    const int level = view.level;
    s.stats.max_level_reached = std::max(s.stats.max_level_reached, level);
    const std::vector<int>& portals = r.links.room_portals[view.cell];
    std::vector<char> masked;
    const std::vector<std::array<NdcRect, 2>> visible = visible_portals(ctx, view, portals, masked);

    // Its surfaces keep the box bit only for portals to mark (passes.hpp).
    LevelView surfaces = view;
    surfaces.box_bits = std::any_of(visible.begin(), visible.end(), [](const std::array<NdcRect, 2>& rects) {
        return !rects[0].empty() || !rects[1].empty();
    });
    draw_level_surfaces(ctx, surfaces, portals, visible);

    // A portal hidden behind the cell's own surfaces (say, a wall) passes the
    // frustum test but not this one: conditional rendering then drops every
    // draw of its subtree, with no read-back on the CPU. Conditional
    // rendering does not nest, so the outermost level decides for everything
    // inside; all its queries are drawn before the first is waited on, so
    // the driver synchronises once.
    const bool occlusion = ctx.frame.occlusion_test && ctx.frame.cull_portals && !s.conditional;
    const std::vector<GLuint> tests =
        occlusion ? test_portal_visibility(ctx, view, portals, visible) : std::vector<GLuint>(portals.size(), 0);
    const std::vector<PortalSteps> steps = portal_steps(ctx, view, visible);

    for (size_t k = 0; k < portals.size(); ++k) {
        const std::array<NdcRect, 2>& rects = visible[k];
        if (rects[0].empty() && rects[1].empty()) {
            s.stats.portal_passes_culled += 1;
            s.stats.portal_passes_masked += masked[k];
            continue;
        }
        if (tests[k]) {
            glBeginConditionalRender(tests[k], GL_QUERY_WAIT);
            s.conditional = true;
        }
        // Mirrors and windows always take the stencil path: their views are
        // blended in place (portal_glass.cpp). A door at the texture level
        // takes the texture unless draw_portal would show the fill.
        const bool door = r.portals[portals[k]].kind == layout::PortalKind::Door;
        if (door && level == ctx.frame.portal_texture_level && ctx.frame.portal_texture_scale > 0.0 &&
            level < ctx.frame.max_depth && s.stats.portal_passes_drawn < ctx.frame.max_portal_passes)
            draw_portal_via_texture(ctx, view, portals[k], rects, k);
        else if (ctx.profiler && level == 0)
            draw_top_portal_profiled(ctx, view, portals[k], rects, steps[k]);
        else
            draw_portal(ctx, view, portals[k], rects, steps[k]);
        if (tests[k]) {
            glEndConditionalRender();
            s.conditional = false;
        }
    }
}

}  // namespace impossible::render
