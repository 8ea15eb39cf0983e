// The drawing steps a portal level is made of (see portal_recursion.cpp):
// per-eye uniforms, the scissor of a portal, its box, the view through it.
#include <algorithm>
#include <cassert>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "math/oblique_projection.hpp"
#include "render/portal_recursion.hpp"
#include "shading/shading.hpp"

namespace impossible::render {

void use_pass(DrawContext& ctx, const LevelView& view, Pass pass, int stencil_ref) {
    ctx.renderer.state->apply(pass_state(pass, ctx.frame.depth == DepthMode::ReversedZ, view.mirrored), stencil_ref);
}

void set_eye_uniforms(const DrawContext& ctx, const LevelView& view, const std::array<NdcRect, 2>& rects) {
    float vp[2][16];
    float rect[2][4];
    float plane[2][4];
    const int eye_w = ctx.frame.eye_width, eye_h = ctx.frame.eye_height;
    // The cell's vertices are relative to its origin: the move to layout
    // coordinates is folded into the matrices and planes here, in double.
    const scene::CellFrame& cell = ctx.renderer.frames[static_cast<size_t>(view.cell)];
    const math::dmat4 from_cell = glm::translate(math::dmat4(1.0), cell.origin);
    for (int e = 0; e < 2; ++e) {
        const EyeView& ev = view.eyes[e];
        const math::dmat4 view_proj = ev.view_proj * from_cell;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) vp[e][c * 4 + r] = static_cast<float>(view_proj[c][r]);
        NdcRect nr = ev.active ? rects[e] : NdcRect::none();
        if (!nr.empty()) {
            // One pixel of margin keeps float rounding from trimming a pixel
            // whose centre the portal covers; the stencil bounds the rest.
            // Never past the eye's own image: in clip-shift mode x = ±1 is
            // the seam between the two eyes.
            nr = intersect(widened(nr, 1.0, eye_w, eye_h), NdcRect{});
        }
        rect[e][0] = static_cast<float>(nr.x0);
        rect[e][1] = static_cast<float>(nr.y0);
        rect[e][2] = static_cast<float>(nr.x1);
        rect[e][3] = static_cast<float>(nr.y1);
        const math::dvec4 cell_plane(math::dvec3(ev.clip_plane),
                                     ev.clip_plane.w + glm::dot(math::dvec3(ev.clip_plane), cell.origin));
        for (int c = 0; c < 4; ++c) plane[e][c] = static_cast<float>(cell_plane[c]);
    }
    const GLuint p = ctx.program.program.get();
    glProgramUniformMatrix4fv(p, ctx.program.view_proj, 2, GL_FALSE, &vp[0][0]);
    glProgramUniform4fv(p, ctx.program.eye_rect, 2, &rect[0][0]);
    glProgramUniform4fv(p, ctx.program.clip_plane, 2, &plane[0][0]);
    glProgramUniform3fv(p, ctx.program.checker_offset, 1, &cell.checker_offset[0]);
}

gl::ScissorRect scissor_of(const DrawContext& ctx, const std::array<NdcRect, 2>& rects, const LevelView& view) {
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

void limit_to_portal(DrawContext& ctx, const LevelView& view, const std::array<NdcRect, 2>& rects) {
    if (ctx.frame.cull_portals) ctx.renderer.state->scissor(scissor_of(ctx, rects, view));
}

void mark_portal(DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects) {
    limit_to_portal(ctx, view, rects);
    use_pass(ctx, view, Pass::PortalMark, view.level);
    draw_portal_box(ctx, view, p, rects);
    clear_depth_in_portal(ctx, view, view.level + 1, rects);
}

void unmark_portal(DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects) {
    limit_to_portal(ctx, view, rects);
    use_pass(ctx, view, Pass::PortalUnmark, view.level + 1);
    draw_portal_box(ctx, view, p, rects);
}

namespace {

// Submits the ranges queued in the renderer's IndirectDraws with the state
// bound now, and counts them.
void submit_queued(DrawContext& ctx) {
    IndirectDraws& queue = ctx.renderer.indirect;
    for (const IndirectDraw& d : queue.pending)
        ctx.stats.triangles += static_cast<long>(d.count / 3) * static_cast<long>(d.instance_count);
    ctx.stats.draw_calls += submit_indirect(queue);
}

int instances_of(const DrawContext& ctx) { return ctx.frame.stereo == StereoMode::TwoPass ? 1 : 2; }

}  // namespace

void draw_range(DrawContext& ctx, const scene::IndexRange& range) {
    assert(ctx.renderer.indirect.pending.empty());  // nothing queued for another state
    queue_range(ctx.renderer.indirect, range, instances_of(ctx));
    submit_queued(ctx);
}

void draw_cell(DrawContext& ctx, const LevelView& view) {
    RendererData& r = ctx.renderer;
    const auto cell = static_cast<std::size_t>(view.cell);
    const std::vector<scene::DrawBatch>* batches = &r.cells[cell];
    if (ctx.frame.cull_portals && ctx.frame.cull_objects && !r.objects[cell].objects.empty()) {
        // Two pixels of margin: one more than the eye rectangles' own.
        visible_batches(r.objects[cell], view, ctx.frame.eye_width, ctx.frame.eye_height, 2.0, r.cull_scratch,
                        r.cull_batches);
        batches = &r.cull_batches;
    }
    // Plain batches with the plain program, queued and submitted together
    // (FrameDesc::multi_draw) before the next batch with materials and at the
    // end; the others with the material variant, whose per-level uniforms
    // are set when it is first needed.
    const auto submit_plain = [&] {
        if (r.indirect.pending.empty()) return;
        r.state->program(ctx.program.program.get());
        submit_queued(ctx);
    };
    bool material_ready = false;
    for (const scene::DrawBatch& b : *batches) {
        if (b.texture < 0 && b.alpha_cutoff < 0.0f) {
            queue_range(r.indirect, b.range, instances_of(ctx));
            if (!ctx.frame.multi_draw) submit_plain();
            continue;
        }
        submit_plain();
        assert(ctx.material_program != nullptr);
        const SceneProgram& m = *ctx.material_program;
        if (!material_ready) {
            const DrawContext with_materials{r, m, ctx.frame, ctx.stats, ctx.projection, ctx.profiler};
            set_eye_uniforms(with_materials, view, {view.eyes[0].rect, view.eyes[1].rect});
            set_cell_id(with_materials, static_cast<unsigned>(view.cell + 1), false);
            glProgramUniform1i(m.program.get(), m.level0, ctx.frame.textures_level0 ? 1 : 0);
            material_ready = true;
        }
        r.state->program(m.program.get());
        glProgramUniform1i(m.program.get(), m.textured, b.texture >= 0 ? 1 : 0);
        glProgramUniform1f(m.program.get(), m.alpha_cutoff, b.alpha_cutoff);
        if (b.texture >= 0)
            glBindTextureUnit(kSceneTextureUnit, r.gpu.textures[static_cast<std::size_t>(b.texture)].get());
        draw_range(ctx, b.range);
    }
    submit_plain();
    r.state->program(ctx.program.program.get());
}

void draw_portal_box(DrawContext& ctx, const LevelView& view, int portal, const std::array<NdcRect, 2>& rects) {
    const scene::PortalInfo& info = ctx.renderer.portals[portal];
    const scene::PortalMesh& mesh = ctx.renderer.portal_meshes[portal];
    assert(info.room == view.cell);  // its box is relative to the cell's frame
    std::array<NdcRect, 2> front = rects, inner = rects;
    bool any_inner = false;
    for (int e = 0; e < 2; ++e) {
        if (!math::in_column(info.rect, view.eyes[e].eye.position)) inner[e] = NdcRect::none();
        else any_inner = true;
    }
    set_eye_uniforms(ctx, view, front);
    draw_range(ctx, mesh.front);
    if (any_inner) {
        set_eye_uniforms(ctx, view, inner);
        draw_range(ctx, mesh.inner);
    }
}

void draw_fill(DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects, int stencil_ref) {
    limit_to_portal(ctx, view, rects);
    use_pass(ctx, view, Pass::PortalFill, stencil_ref);
    set_cell_id(ctx, shading::kFillId, true);
    const ColourQueryScope colour(ctx.profiler);
    draw_portal_box(ctx, view, p, rects);
    ctx.stats.portal_fills += 1;
}

namespace {

// The view of `cell` from the eyes moved by m, which stand behind `exit`
// (of `cell`) or, for an eye that crossed the plane ahead of the head, in
// front of it; behind it, exit's plane clips.
LevelView moved_view(const DrawContext& ctx, const LevelView& view, const math::dmat4& m, int cell, int exit,
                     const std::array<NdcRect, 2>& rects) {
    const scene::PortalInfo& b = ctx.renderer.portals[exit];
    LevelView child;
    child.cell = cell;
    child.level = view.level + 1;
    child.entered_by = exit;
    child.mirrored = view.mirrored;
    child.weight = view.weight;
    for (int e = 0; e < 2; ++e) {
        EyeView& ev = child.eyes[e];
        ev.active = view.eyes[e].active && !rects[e].empty();
        ev.eye = math::transform_eye(m, view.eyes[e].eye);
        const math::dmat4 view_matrix = math::view_matrix(ev.eye);
        ev.view_proj = ctx.projection * view_matrix;
        ev.rect = rects[e];
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

}  // namespace

LevelView child_view(const DrawContext& ctx, const LevelView& view, int portal, const std::array<NdcRect, 2>& rects,
                     double weight_factor) {
    // A virtual eye behind B sees B's room only in front of B's plane; one
    // already in front of B (the real eye crossed A before the head) stands
    // in B's room and needs no plane.
    const scene::PortalInfo& a = ctx.renderer.portals[portal];
    LevelView child = moved_view(ctx, view, ctx.renderer.links.transfer[portal], ctx.renderer.portals[a.target].room,
                                 a.target, rects);
    child.weight *= weight_factor;
    return child;
}

LevelView reflected_view(const DrawContext& ctx, const LevelView& view, int portal,
                         const std::array<NdcRect, 2>& rects, double weight_factor) {
    // The mirrored eye is behind the plane (the real one is in front, or the
    // mirror would not be visible); the plane clips what lies behind it.
    LevelView child = moved_view(ctx, view, ctx.renderer.links.reflection[portal], view.cell, portal, rects);
    child.mirrored = !view.mirrored;
    child.weight *= weight_factor;
    return child;
}

}  // namespace impossible::render
