// The drawing steps a portal level is made of (see portal_recursion.cpp):
// marking and unmarking a portal, its box, the fill, a cell's batches, the
// view through a portal.
#include <algorithm>
#include <cassert>
#include <cmath>

#include "math/crossing.hpp"
#include "math/oblique_projection.hpp"
#include "render/lights/light_draw.hpp"
#include "render/objects/object_draw.hpp"
#include "render/portals/portal_draw.hpp"
#include "shading/shading.hpp"

namespace impossible::render {

void clear_depth_in_portal(const DrawContext& ctx, const LevelView& view, int stencil_ref,
                           const std::array<NdcRect, 2>& rects, Pass pass) {
    const ClearDepthProgram& clear = ctx.programs.clear_depth;
    const GLuint program = clear.program.get();
    const TargetDraw draw{pass, stencil_ref, program, portal_scissor(ctx, view, rects)};
    glProgramUniform1f(program, clear.far_depth, far_depth(ctx.frame));
    if (!ctx.frame.cull_portals) {
        glProgramUniform1i(program, clear.eye_quads, 0);
        draw_full_target(ctx, view, draw);
        return;
    }
    // One rectangle per eye that sees the portal, in one instanced draw: the
    // scissor of the pair spans the seam between the two halves of the
    // target, and the triangle would cost in proportion to its area even
    // where the stencil fails. Each rectangle is the eye's, widened by two
    // pixels (the marked pixels lie within one, set_eye_uniforms), in the
    // viewport's coordinates: the whole target's in clip-shift and
    // viewport-index mode (drawn through the widened viewport 0), the eye's
    // own in two-pass mode.
    const bool side_by_side = ctx.frame.stereo != StereoMode::TwoPass;
    float quads[2][4];
    int count = 0;
    for (int e = 0; e < 2; ++e) {
        if (!view.eyes[e].active || rects[e].empty()) continue;
        const NdcRect q = intersect(widened(rects[e], 2.0, ctx.frame.eye_width, ctx.frame.eye_height), NdcRect{});
        const double shift = side_by_side ? (e == 0 ? -1.0 : 1.0) : 0.0;
        const double scale = side_by_side ? 0.5 : 1.0;
        quads[count][0] = static_cast<float>(scale * (q.x0 + shift));
        quads[count][1] = static_cast<float>(q.y0);
        quads[count][2] = static_cast<float>(scale * (q.x1 + shift));
        quads[count][3] = static_cast<float>(q.y1);
        ++count;
    }
    if (count == 0) return;
    glProgramUniform4fv(program, clear.rects, count, &quads[0][0]);
    glProgramUniform1i(program, clear.eye_quads, 1);
    draw_full_target(ctx, view, draw, count);
}

void mark_portal(const DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects,
                 const PortalSteps& steps) {
    if (steps.one_draw_mark) {
        clear_depth_in_portal(ctx, view, view.level, rects, Pass::PortalMarkReset);
        ctx.scratch.stats.one_draw_marks += 1;
        return;
    }
    draw_portal_box(ctx, view,
                    {Pass::PortalMark, view.level, &cell_program(ctx, view), portal_scissor(ctx, view, rects)}, p,
                    rects);
    clear_depth_in_portal(ctx, view, view.level + 1, rects);
}

void unmark_portal(const DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects,
                   const PortalSteps& steps) {
    if (!steps.unmark) {
        ctx.scratch.stats.unmarks_skipped += 1;
        return;
    }
    draw_portal_box(ctx, view,
                    {Pass::PortalUnmark, view.level, &cell_program(ctx, view), portal_scissor(ctx, view, rects)}, p,
                    rects);
}

namespace {

// A level's draws of its cell into scratch.cull_draws, in the cell's order:
// every batch; with per-object culling those of the props an eye may see;
// and with FrameDesc::cull_box_faces the faces of the visible boxes that an
// eye may see from the front, as ranges of the face stream, uploaded here.
// Returns where this level's indices start in the stream.
std::uint32_t level_draws(const DrawContext& ctx, const LevelView& view) {
    const SceneData& r = ctx.scene;
    FrameScratch& s = ctx.scratch;
    const auto cell = static_cast<std::size_t>(view.cell);
    const bool culled = ctx.frame.cull_portals && ctx.frame.cull_objects && !r.objects[cell].objects.empty();
    // Two pixels of margin: one more than the eye rectangles' own.
    if (culled && ctx.frame.cull_box_faces) {
        const BoxFaceView faces = box_face_view(view, ctx.frame.eye_width, ctx.frame.eye_height, ctx.frame.samples);
        visible_draws(r.objects[cell], view, ctx.frame.eye_width, ctx.frame.eye_height, 2.0, faces, s.cull,
                      s.faces.pending, s.cull_draws);
        return upload_faces(s.faces, r.gpu.face_indices.get());
    }
    const std::vector<scene::DrawBatch>* batches = &r.cells[cell];
    if (culled) {
        visible_batches(r.objects[cell], view, ctx.frame.eye_width, ctx.frame.eye_height, 2.0, s.cull, s.cull_batches);
        batches = &s.cull_batches;
    }
    s.cull_draws.clear();
    for (const scene::DrawBatch& b : *batches) s.cull_draws.push_back({b, false});
    return 0;
}

}  // namespace

void draw_cell(const DrawContext& ctx, const LevelView& view, const SceneDraw& draw) {
    const SceneData& r = ctx.scene;
    FrameScratch& s = ctx.scratch;
    const std::uint32_t face_base = level_draws(ctx, view);
    // Plain batches queued and submitted together (FrameDesc::multi_draw)
    // before the next batch with materials and at the end; the others with
    // the material variant, whose per-level uniforms are set when it is
    // first needed.
    SceneDraw with_materials = draw;
    const SceneProgram* material_program =
        ctx.material_program ? &cell_program(ctx, view, kMaterials | light_flags(ctx, view.cell, &view)) : nullptr;
    with_materials.program = material_program;
    bool material_ready = false;
    for (const VisibleDraw& d : s.cull_draws) {
        const scene::DrawBatch& b = d.batch;
        if (d.faces) {  // box faces, from the stream (plain)
            submit_queued(ctx, view, draw);
            queue_range(s.indirect, {b.range.first + face_base, b.range.count}, instances_of(ctx));
            submit_queued(ctx, view, draw, r.gpu.face_vao.get());
            continue;
        }
        if (b.texture < 0 && b.alpha_cutoff < 0.0f) {
            queue_range(s.indirect, b.range, instances_of(ctx));
            if (!ctx.frame.multi_draw) submit_queued(ctx, view, draw);
            continue;
        }
        submit_queued(ctx, view, draw);
        assert(material_program != nullptr);
        const SceneProgram& m = *material_program;
        if (!material_ready) {
            set_eye_uniforms(ctx, view, m, {view.eyes[0].rect, view.eyes[1].rect});
            set_cell_id(m, static_cast<unsigned>(view.cell + 1), false);
            set_room_lights(ctx, m, view.cell, false);
            glProgramUniform1i(m.program.get(), m.mip_level0, ctx.frame.textures_mip_level0 ? 1 : 0);
            material_ready = true;
        }
        glProgramUniform1i(m.program.get(), m.textured, b.texture >= 0 ? 1 : 0);
        glProgramUniform1f(m.program.get(), m.alpha_cutoff, b.alpha_cutoff);
        const GLuint texture = b.texture >= 0 ? r.gpu.textures[static_cast<std::size_t>(b.texture)].get() : 0;
        ctx.state.texture(kSceneTextureUnit, texture);
        draw_range(ctx, view, with_materials, b.range);
    }
    submit_queued(ctx, view, draw);
}

void draw_portal_box(const DrawContext& ctx, const LevelView& view, const SceneDraw& draw, int portal,
                     const std::array<NdcRect, 2>& rects) {
    const scene::PortalInfo& info = ctx.scene.portals[portal];
    const scene::PortalMesh& mesh = ctx.scene.portal_meshes[portal];
    assert(info.room == view.cell);  // its box is relative to the cell's origin
    // The inner faces for the eyes that have them: behind the plane they
    // win a coplanar tie, in front (where they lie behind the front face)
    // they lose it as the front face does (docs/choices.md, "Coplanar ties").
    std::array<NdcRect, 2> inner_behind = rects, inner_in_front = rects;
    bool any_behind = false, any_in_front = false;
    for (int e = 0; e < 2; ++e) {
        const math::Eye& eye = view.eyes[e].eye;
        if (!math::has_inner_faces(info.rect, eye.position, eye.head)) {
            inner_behind[e] = inner_in_front[e] = NdcRect::none();
        } else if (math::signed_distance(info.rect, eye.position) < 0.0) {
            inner_in_front[e] = NdcRect::none();
            any_behind = true;
        } else {
            inner_behind[e] = NdcRect::none();
            any_in_front = true;
        }
    }
    const bool door = info.kind == layout::PortalKind::Door;
    SceneDraw d = draw;
    d.tie = door ? CoplanarTie::Loses : CoplanarTie::None;
    set_eye_uniforms(ctx, view, *draw.program, rects);
    draw_range(ctx, view, d, mesh.front);
    if (any_in_front) {
        set_eye_uniforms(ctx, view, *draw.program, inner_in_front);
        draw_range(ctx, view, d, mesh.inner);
    }
    if (any_behind) {
        d.tie = CoplanarTie::Wins;
        set_eye_uniforms(ctx, view, *draw.program, inner_behind);
        draw_range(ctx, view, d, mesh.inner);
    }
}

void draw_fill(const DrawContext& ctx, const LevelView& view, int p, const std::array<NdcRect, 2>& rects,
               int stencil_ref) {
    const SceneProgram& program = cell_program(ctx, view);
    set_cell_id(program, shading::kFillId, true);
    const ColourQueryScope colour(ctx.profiler);
    draw_portal_box(ctx, view, {Pass::PortalFill, stencil_ref, &program, portal_scissor(ctx, view, rects)}, p, rects);
    ctx.scratch.stats.portal_fills += 1;
}

namespace {

// The view of `cell` from the eyes moved by m, which stand behind `exit`
// (of `cell`) or, for an eye that crossed the plane ahead of the head, in
// front of it; behind it, exit's plane clips.
LevelView moved_view(const DrawContext& ctx, const LevelView& view, const math::dmat4& m, int cell, int exit,
                     const std::array<NdcRect, 2>& rects) {
    const scene::PortalInfo& b = ctx.scene.portals[exit];
    LevelView child;
    child.cell = cell;
    child.level = view.level + 1;
    child.entered_by = exit;
    child.mirrored = view.mirrored;
    child.weight = view.weight;
    child.through_portal = true;
    for (int e = 0; e < 2; ++e) {
        EyeView& ev = child.eyes[e];
        ev.active = view.eyes[e].active && !rects[e].empty();
        ev.eye = math::transform_eye(m, view.eyes[e].eye);
        const math::dmat4 view_matrix = math::view_matrix(ev.eye);
        ev.view_proj = ctx.projections[e] * view_matrix;
        ev.rect = rects[e];
        ev.behind_exit = math::signed_distance(b.rect, ev.eye.position) < 0.0;
        if (!ev.behind_exit) continue;
        const math::dvec4 plane = math::portal_plane(b.rect);
        ev.exit_plane = plane;
        if (ctx.frame.clip == ClipMode::Oblique) {
            const math::dvec4 plane_eye = math::transform_plane(view_matrix, plane);
            ev.view_proj =
                (ctx.frame.depth == DepthMode::ReversedZ ? math::oblique_reversed_z(ctx.projections[e], plane_eye)
                                                         : math::oblique_standard(ctx.projections[e], plane_eye)) *
                view_matrix;
        } else
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
    const scene::PortalInfo& a = ctx.scene.portals[portal];
    LevelView child =
        moved_view(ctx, view, ctx.scene.links.transfer[portal], ctx.scene.portals[a.target].room, a.target, rects);
    child.weight *= weight_factor;
    return child;
}

LevelView reflected_view(const DrawContext& ctx, const LevelView& view, int portal, const std::array<NdcRect, 2>& rects,
                         double weight_factor) {
    // The mirrored eye is behind the plane (the real one is in front, or the
    // mirror would not be visible); the plane clips what lies behind it.
    LevelView child = moved_view(ctx, view, ctx.scene.links.reflection[portal], view.cell, portal, rects);
    child.mirrored = !view.mirrored;
    child.weight *= weight_factor;
    return child;
}

}  // namespace impossible::render
