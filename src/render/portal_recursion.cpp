// Recursive portal rendering with the stencil buffer, both eyes at once.
//
// The scheme is the classic stencil-portal recursion (as in e.g. Kilgard,
// "Improving Shadows and Reflections via the Stencil Buffer", NVIDIA 1999, and
// the portal renderers that followed): the stencil value of a pixel is the
// recursion level whose view it shows. Per portal: mark the pixels where its
// box is the visible surface (level → level + 1), reset depth there, draw the
// target room from the virtual cameras M_AB · eye clipped at the target
// portal's plane, recurse, then unmark and put the box's depth back so that
// it occludes what the rest of this level draws. Every draw is one instanced
// draw for both eyes; an eye that cannot see a portal gets an empty
// rectangle, which its clip distances turn into no work.
#include "render/portal_recursion.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "math/oblique_projection.hpp"
#include "render/passes.hpp"

namespace impossible::render {
namespace {

// Uploads the per-eye uniforms of a draw: matrices, rectangles, planes.
void set_eye_uniforms(const DrawContext& ctx, const LevelView& view,
                      const std::array<NdcRect, 2>& rects) {
    float vp[2][16];
    float rect[2][4];
    float plane[2][4];
    const int eye_w = ctx.frame.eye_width, eye_h = ctx.frame.eye_height;
    for (int e = 0; e < 2; ++e) {
        const EyeView& ev = view.eyes[e];
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) vp[e][c * 4 + r] = static_cast<float>(ev.view_proj[c][r]);
        NdcRect nr = ev.active ? rects[e] : NdcRect::none();
        if (!nr.empty()) {
            // One pixel of margin keeps float rounding from trimming a pixel
            // whose centre the portal covers; the stencil bounds the rest.
            // Never past the eye's own image: in clip-shift mode x = ±1 is
            // the seam between the two eyes.
            const double mx = 2.0 / eye_w, my = 2.0 / eye_h;
            nr = intersect({nr.x0 - mx, nr.y0 - my, nr.x1 + mx, nr.y1 + my}, NdcRect{});
        }
        rect[e][0] = static_cast<float>(nr.x0);
        rect[e][1] = static_cast<float>(nr.y0);
        rect[e][2] = static_cast<float>(nr.x1);
        rect[e][3] = static_cast<float>(nr.y1);
        for (int c = 0; c < 4; ++c) plane[e][c] = static_cast<float>(ev.clip_plane[c]);
    }
    const GLuint p = ctx.program.program.get();
    glProgramUniformMatrix4fv(p, ctx.program.view_proj, 2, GL_FALSE, &vp[0][0]);
    glProgramUniform4fv(p, ctx.program.eye_rect, 2, &rect[0][0]);
    glProgramUniform4fv(p, ctx.program.clip_plane, 2, &plane[0][0]);
}

// The pixel rectangle (GL window coordinates) covering both eyes' rects.
gl::ScissorRect scissor_of(const DrawContext& ctx, const std::array<NdcRect, 2>& rects,
                           const LevelView& view) {
    const int w = ctx.frame.eye_width, h = ctx.frame.eye_height;
    int x0 = 2 * w, y0 = h, x1 = 0, y1 = 0;
    for (int e = 0; e < 2; ++e) {
        if (!view.eyes[e].active || rects[e].empty()) continue;
        const NdcRect& r = rects[e];
        x0 = std::min(x0, e * w + static_cast<int>(std::floor((r.x0 + 1.0) * 0.5 * w)) - 1);
        x1 = std::max(x1, e * w + static_cast<int>(std::ceil((r.x1 + 1.0) * 0.5 * w)) + 1);
        y0 = std::min(y0, static_cast<int>(std::floor((r.y0 + 1.0) * 0.5 * h)) - 1);
        y1 = std::max(y1, static_cast<int>(std::ceil((r.y1 + 1.0) * 0.5 * h)) + 1);
    }
    x0 = std::max(x0, 0); y0 = std::max(y0, 0);
    x1 = std::min(x1, 2 * w); y1 = std::min(y1, h);
    return {x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
}

void draw_range(DrawContext& ctx, const scene::IndexRange& range) {
    if (range.count == 0) return;
    const int instances = ctx.frame.stereo == StereoMode::TwoPass ? 1 : 2;
    glDrawElementsInstanced(GL_TRIANGLES, static_cast<GLsizei>(range.count), GL_UNSIGNED_INT,
                            reinterpret_cast<const void*>(static_cast<uintptr_t>(range.first) * 4),
                            instances);
    ctx.stats.draw_calls += 1;
    ctx.stats.triangles += static_cast<long>(range.count / 3) * instances;
}

void use_pass(DrawContext& ctx, Pass pass, int stencil_ref) {
    ctx.renderer.state.apply(pass_state(pass, ctx.frame.depth == DepthMode::ReversedZ), stencil_ref);
}

void set_cell_id(const DrawContext& ctx, unsigned id, bool unshaded) {
    const GLuint p = ctx.program.program.get();
    glProgramUniform1ui(p, ctx.program.cell_id, id);
    glProgramUniform1i(p, ctx.program.unshaded, unshaded ? 1 : 0);
}

// Brackets the colour draws of a pass with a GL_SAMPLES_PASSED query when
// profiling; nothing otherwise.
struct ColourQueryScope {
    FrameProfiler* profiler;
    explicit ColourQueryScope(FrameProfiler* p) : profiler(p) {
        if (!profiler) return;
        GLuint q = 0;
        glCreateQueries(GL_SAMPLES_PASSED, 1, &q);
        profiler->queries.push_back({q, profiler->top_portal});
        glBeginQuery(GL_SAMPLES_PASSED, q);
    }
    ~ColourQueryScope() {
        if (profiler) glEndQuery(GL_SAMPLES_PASSED);
    }
    ColourQueryScope(const ColourQueryScope&) = delete;
    ColourQueryScope& operator=(const ColourQueryScope&) = delete;
};

// Draws a portal's box for the eyes with a non-empty rect: the front face for
// eyes in front of it, the inner faces for eyes in its column.
void draw_portal_box(DrawContext& ctx, const LevelView& view, int portal,
                     const std::array<NdcRect, 2>& rects) {
    const math::PortalRect& rect = ctx.renderer.layout.portals[portal].rect;
    const scene::PortalMesh& mesh = ctx.renderer.scene.portals[portal];
    std::array<NdcRect, 2> front = rects, inner = rects;
    bool any_inner = false;
    for (int e = 0; e < 2; ++e) {
        if (!math::in_column(rect, view.eyes[e].eye.position)) inner[e] = NdcRect::none();
        else any_inner = true;
    }
    set_eye_uniforms(ctx, view, front);
    draw_range(ctx, mesh.front);
    if (any_inner) {
        set_eye_uniforms(ctx, view, inner);
        draw_range(ctx, mesh.inner);
    }
}

void clear_depth_in_portal(DrawContext& ctx, int stencil_ref) {
    use_pass(ctx, Pass::ClearDepth, stencil_ref);
    glUseProgram(ctx.renderer.clear_depth.program.get());
    glProgramUniform1f(ctx.renderer.clear_depth.program.get(), ctx.renderer.clear_depth.far_depth,
                       ctx.frame.depth == DepthMode::ReversedZ ? 0.0f : 1.0f);
    glBindVertexArray(ctx.renderer.empty_vao.get());
    // The clear triangle has no eye: with per-eye viewports it is drawn
    // through viewport 0, widened to the whole target for the moment.
    const bool indexed = ctx.frame.stereo == StereoMode::ViewportIndex;
    const float w = static_cast<float>(ctx.frame.eye_width), h = static_cast<float>(ctx.frame.eye_height);
    if (indexed) glViewportIndexedf(0, 0.0f, 0.0f, 2.0f * w, h);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    if (indexed) glViewportIndexedf(0, 0.0f, 0.0f, w, h);
    ctx.stats.draw_calls += 1;
    glBindVertexArray(ctx.renderer.gpu.vao.get());
    glUseProgram(ctx.program.program.get());
}

// The view through `portal` (of view.cell) into its target's room.
LevelView child_view(const DrawContext& ctx, const LevelView& view, int portal,
                     const std::array<NdcRect, 2>& rects) {
    const layout::Portal& a = ctx.renderer.layout.portals[portal];
    const layout::Portal& b = ctx.renderer.layout.portals[a.target];
    const math::dmat4& m = ctx.renderer.transfer[portal];
    LevelView child;
    child.cell = b.room;
    child.level = view.level + 1;
    child.entered_by = a.target;
    for (int e = 0; e < 2; ++e) {
        EyeView& ev = child.eyes[e];
        ev.active = view.eyes[e].active && !rects[e].empty();
        ev.eye = math::transform_eye(m, view.eyes[e].eye);
        const math::dmat4 view_matrix = math::view_matrix(ev.eye);
        ev.view_proj = ctx.projection * view_matrix;
        ev.rect = rects[e];
        // A virtual eye behind B sees B's room only in front of B's plane;
        // one already in front of B (the real eye crossed A before the head)
        // stands in B's room and needs no plane.
        ev.behind_exit = math::signed_distance(b.rect, ev.eye.position) < 0.0;
        if (!ev.behind_exit) continue;
        const math::dvec4 plane = math::portal_plane(b.rect);
        if (ctx.frame.clip == ClipMode::Oblique) {
            const math::dvec4 plane_eye = math::transform_plane(view_matrix, plane);
            ev.view_proj = (ctx.frame.depth == DepthMode::ReversedZ
                                ? math::oblique_reversed_z(ctx.projection, plane_eye)
                                : math::oblique_standard(ctx.projection, plane_eye)) *
                           view_matrix;
        }
        else
            ev.clip_plane = plane;
    }
    return child;
}

// One visible portal of `view`: the fill at the depth limit, or mark, depth
// reset, the view through it (recursively) and unmark.
void draw_portal(DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects) {
    Renderer& r = ctx.renderer;
    const int level = view.level;
    if (ctx.frame.cull_portals) r.state.scissor(scissor_of(ctx, rects, view));
    if (level >= ctx.frame.max_depth) {
        use_pass(ctx, Pass::PortalFill, level);
        set_cell_id(ctx, 255, true);
        const ColourQueryScope colour(ctx.profiler);
        draw_portal_box(ctx, view, p, rects);
        ctx.stats.portal_fills += 1;
        return;
    }
    use_pass(ctx, Pass::PortalMark, level);
    draw_portal_box(ctx, view, p, rects);
    clear_depth_in_portal(ctx, level + 1);

    ctx.stats.portal_passes_drawn += 1;
    draw_level(ctx, child_view(ctx, view, p, rects));

    if (ctx.frame.cull_portals) r.state.scissor(scissor_of(ctx, rects, view));
    use_pass(ctx, Pass::PortalUnmark, level + 1);
    draw_portal_box(ctx, view, p, rects);
}

// Render-to-texture (the classic technique, for comparison): the view
// through portal `p` of the head's cell is drawn into a texture of scale ×
// the eye size, both eyes side by side (recursion inside it by stencil), and
// the box then shows that texture where it is the visible surface.
void draw_portal_via_texture(DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects,
                             size_t slot) {
    Renderer& r = ctx.renderer;
    const FrameDesc& f = ctx.frame;
    FrameDesc inner = f;
    inner.eye_width = std::max(1, static_cast<int>(std::lround(f.eye_width * f.portal_texture_scale)));
    inner.eye_height = std::max(1, static_cast<int>(std::lround(f.eye_height * f.portal_texture_scale)));
    inner.portal_texture_scale = 0.0;
    if (r.portal_textures.size() <= slot) r.portal_textures.resize(slot + 1);
    Target& texture = r.portal_textures[slot];
    if (texture.width != 2 * inner.eye_width || texture.height != inner.eye_height || texture.depth != f.depth ||
        !texture.framebuffer) {
        TargetResult made = create_sampled_target(2 * inner.eye_width, inner.eye_height, f.depth);
        if (!made.error.empty()) return;  // an incomplete target shows nothing through this portal
        texture = std::move(made.target);
    }

    // The view through the portal, at level + 1 everywhere in the texture.
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, texture.framebuffer.get());
    glViewport(0, 0, texture.width, texture.height);
    clear_target(r, texture, view.level + 1);
    DrawContext inside{r, ctx.program, inner, ctx.stats, ctx.projection, ctx.profiler};
    ctx.stats.portal_passes_drawn += 1;
    draw_level(inside, child_view(ctx, view, p, rects));

    // The box shows the texture where it is the visible surface.
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, r.target.framebuffer.get());
    glViewport(0, 0, 2 * f.eye_width, f.eye_height);
    if (f.cull_portals) r.state.scissor(scissor_of(ctx, rects, view));
    else r.state.no_scissor();
    const SceneProgram& shows = *r.portal_texture_program;
    glUseProgram(shows.program.get());
    glProgramUniform2f(shows.program.get(), shows.target_size, float(2 * f.eye_width), float(f.eye_height));
    glBindTextureUnit(0, texture.color_texture.get());
    glBindTextureUnit(1, texture.ids_texture.get());
    DrawContext outside{r, shows, f, ctx.stats, ctx.projection, nullptr};
    use_pass(outside, Pass::PortalTexture, view.level);
    {
        const ColourQueryScope colour(ctx.profiler);
        draw_portal_box(outside, view, p, rects);
    }
    glBindTextureUnit(0, 0);
    glBindTextureUnit(1, 0);
    glUseProgram(ctx.program.program.get());
}

// One occlusion query per visible portal of this level, drawn after the
// cell's surfaces: whether any pixel of the box is visible. Zero for every
// portal that does not pass (no query there).
std::vector<GLuint> test_portal_visibility(DrawContext& ctx, const LevelView& view, const std::vector<int>& portals,
                                           const std::vector<std::array<NdcRect, 2>>& visible) {
    Renderer& r = ctx.renderer;
    std::vector<GLuint> queries(portals.size(), 0);
    use_pass(ctx, Pass::PortalTest, view.level);
    for (size_t k = 0; k < portals.size(); ++k) {
        if (visible[k][0].empty() && visible[k][1].empty()) continue;
        if (ctx.mark_queries_used == r.mark_queries.size())
            r.mark_queries.push_back(gl::create_query(GL_ANY_SAMPLES_PASSED));
        queries[k] = r.mark_queries[ctx.mark_queries_used++].get();
        glBeginQuery(GL_ANY_SAMPLES_PASSED, queries[k]);
        draw_portal_box(ctx, view, portals[k], visible[k]);
        glEndQuery(GL_ANY_SAMPLES_PASSED);
    }
    return queries;
}

// draw_portal for a portal of the head's cell, timed: glFinish before and
// after, so the time is the GPU work of its whole subtree (and the CPU work
// of submitting it). Two-pass stereo adds both eyes' times.
void draw_top_portal_profiled(DrawContext& ctx, const LevelView& view, int p,
                              const std::array<NdcRect, 2>& rects) {
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    ctx.profiler->top_portal = p;
    draw_portal(ctx, view, p, rects);
    glFinish();
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    ctx.profiler->top_portal = -1;
    std::vector<FrameStats::PortalCost>& costs = ctx.stats.portal_costs;
    auto it = std::find_if(costs.begin(), costs.end(), [p](const auto& c) { return c.portal == p; });
    if (it == costs.end()) costs.push_back({p, ms, 0});
    else it->ms += ms;
}

}  // namespace

void collect_profile(FrameProfiler& profiler, FrameStats& stats) {
    for (const FrameProfiler::ColourQuery& q : profiler.queries) {
        GLuint64 samples = 0;
        glGetQueryObjectui64v(q.query, GL_QUERY_RESULT, &samples);
        glDeleteQueries(1, &q.query);
        stats.colour_fragments += static_cast<long>(samples);
        for (FrameStats::PortalCost& c : stats.portal_costs)
            if (c.portal == q.top_portal) c.colour_fragments += static_cast<long>(samples);
    }
    profiler.queries.clear();
}

void draw_level(DrawContext& ctx, const LevelView& view) {
    Renderer& r = ctx.renderer;
    const int level = view.level;
    ctx.stats.max_level_reached = std::max(ctx.stats.max_level_reached, level);
    const std::array<NdcRect, 2> view_rects = {view.eyes[0].rect, view.eyes[1].rect};

    // Which portals each eye can see. The portal the view came out of lies
    // behind a virtual eye that stands behind it, where the plane clips it.
    const std::vector<int>& portals = r.portals_of_room[view.cell];
    std::vector<std::array<NdcRect, 2>> visible(portals.size());
    for (size_t k = 0; k < portals.size(); ++k) {
        const int p = portals[k];
        for (int e = 0; e < 2; ++e) {
            const EyeView& ev = view.eyes[e];
            const bool behind_exit = p == view.entered_by && ev.behind_exit;
            if (behind_exit || !ev.active) visible[k][e] = NdcRect::none();
            else if (ctx.frame.cull_portals) visible[k][e] = portal_rect(r.layout.portals[p].rect, ev);
            else visible[k][e] = ev.rect;
        }
    }

    // Portal boxes into depth first, so that portals and surfaces occlude each
    // other, and the cell's surfaces behind a portal fail the depth test
    // instead of being drawn and then covered by the view through it.
    use_pass(ctx, Pass::PortalDepth, level);
    for (size_t k = 0; k < portals.size(); ++k)
        if (!visible[k][0].empty() || !visible[k][1].empty()) draw_portal_box(ctx, view, portals[k], visible[k]);

    // The cell's own surfaces.
    use_pass(ctx, Pass::Scene, level);
    set_eye_uniforms(ctx, view, view_rects);
    set_cell_id(ctx, static_cast<unsigned>(view.cell + 1), false);
    {
        const ColourQueryScope colour(ctx.profiler);
        draw_range(ctx, r.scene.cells[view.cell]);
    }

    // A portal hidden behind the cell's own surfaces (say, a wall) passes the
    // frustum test but not this one: conditional rendering then drops every
    // draw of its subtree, with no read-back on the CPU. Conditional
    // rendering does not nest, so the outermost level decides for everything
    // inside; all its queries are drawn before the first is waited on, so
    // the driver synchronises once.
    const bool occlusion = ctx.frame.occlusion_test && ctx.frame.cull_portals && !ctx.conditional;
    const std::vector<GLuint> tests =
        occlusion ? test_portal_visibility(ctx, view, portals, visible) : std::vector<GLuint>(portals.size(), 0);

    for (size_t k = 0; k < portals.size(); ++k) {
        const std::array<NdcRect, 2>& rects = visible[k];
        if (rects[0].empty() && rects[1].empty()) {
            ctx.stats.portal_passes_culled += 1;
            continue;
        }
        if (tests[k]) {
            glBeginConditionalRender(tests[k], GL_QUERY_WAIT);
            ctx.conditional = true;
        }
        if (level == 0 && ctx.frame.portal_texture_scale > 0.0) draw_portal_via_texture(ctx, view, portals[k], rects, k);
        else if (ctx.profiler && level == 0) draw_top_portal_profiled(ctx, view, portals[k], rects);
        else draw_portal(ctx, view, portals[k], rects);
        if (tests[k]) {
            glEndConditionalRender();
            ctx.conditional = false;
        }
    }
    r.state.no_scissor();
}

}  // namespace impossible::render
