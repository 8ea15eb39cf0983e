// The draws of a frame and the state each one names (see draw_state.hpp).
#include "render/draw/draw_state.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace impossible::render {
namespace {

// The polygon offsets of a door box's faces in a coplanar tie
// (docs/choices.md, "Coplanar ties"). A front face meets the surface it ties
// with only along an edge, where both depths are one value interpolated
// over two triangles: two of the depth buffer's least steps cover that, and
// a slope term would move the face behind surfaces a fraction of a pixel
// behind it. An inner face lies in the surface's plane over its whole area,
// where interpolation over a large triangle (a room's floor) differs by up
// to a fraction of the face's depth step per pixel: one step is added.
constexpr float kLosesOffsetFactor = 0.0f;
constexpr float kWinsOffsetFactor = 1.0f;
constexpr float kCoplanarOffsetUnits = 2.0f;

gl::WindowRect whole_target(const FrameDesc& frame) { return {0, 0, 2 * frame.eye_width, frame.eye_height}; }

gl::WindowRect eye_viewport(const FrameDesc& frame, int eye) {
    assert(eye == 0 || eye == 1);  // two-pass stereo draws one eye at a time
    return {eye * frame.eye_width, 0, frame.eye_width, frame.eye_height};
}

// What every draw names: its target, depth convention, pass state (for the
// view's winding), level (the stencil reference), program and scissor.
void bind_common(const DrawContext& ctx, const LevelView& view, Pass pass, int stencil_ref, GLuint program,
                 const Scissor& scissor, int clip_distances = -1, CoplanarTie tie = CoplanarTie::None) {
    gl::StateCache& state = ctx.state;
    const bool reversed_z = ctx.frame.depth == DepthMode::ReversedZ;
    state.draw_framebuffer(ctx.target.framebuffer.get());
    // Reversed-Z: depth 1 at the near plane, 0 at infinity, in a float buffer.
    state.clip_control(reversed_z ? GL_ZERO_TO_ONE : GL_NEGATIVE_ONE_TO_ONE);
    gl::PassState pass_gl = pass_state(pass, reversed_z, view.mirrored);
    if (clip_distances >= 0) pass_gl.clip_distances = clip_distances;
    if (tie != CoplanarTie::None) {
        // Towards the eye is greater depth with reversed-Z, smaller with
        // standard depth (docs/choices.md, "Coplanar ties").
        const float towards = (tie == CoplanarTie::Wins) == reversed_z ? 1.0f : -1.0f;
        pass_gl.offset_factor = towards * (tie == CoplanarTie::Wins ? kWinsOffsetFactor : kLosesOffsetFactor);
        pass_gl.offset_units = towards * kCoplanarOffsetUnits;
    }
    // The draw names a level; the stencil holds it encoded (passes.hpp).
    const GLint reference = stencil_reference(pass, stencil_ref, ctx.frame.max_depth, view.box_bits, pass_gl.stencil);
    state.apply(pass_gl, reference);
    state.program(program);
    if (scissor)
        state.scissor(*scissor);
    else
        state.no_scissor();
}

}  // namespace

void bind_draw(const DrawContext& ctx, const LevelView& view, const SceneDraw& draw) {
    assert(draw.program != nullptr);
    bind_common(ctx, view, draw.pass, draw.stencil_ref, draw.program->program.get(), draw.scissor, draw.clip_distances,
                draw.tie);
    gl::StateCache& state = ctx.state;
    switch (ctx.frame.stereo) {
        case StereoMode::ClipShift: state.viewport(whole_target(ctx.frame)); break;
        case StereoMode::ViewportIndex:
            state.viewport_indexed(0, eye_viewport(ctx.frame, 0));
            state.viewport_indexed(1, eye_viewport(ctx.frame, 1));
            break;
        case StereoMode::TwoPass: state.viewport(eye_viewport(ctx.frame, ctx.eye)); break;
    }
    state.vertex_array(ctx.scene.gpu.vao.get());
}

void bind_draw(const DrawContext& ctx, const LevelView& view, const TargetDraw& draw) {
    bind_common(ctx, view, draw.pass, draw.stencil_ref, draw.program, draw.scissor);
    gl::StateCache& state = ctx.state;
    if (kPassStates[static_cast<size_t>(draw.pass)].blend != gl::Blend::Replace)
        state.blend_color(draw.blend_color.r, draw.blend_color.g, draw.blend_color.b, 1.0f);
    // The triangle has no eye: with per-eye viewports it is drawn through
    // viewport 0, which then spans the whole target.
    switch (ctx.frame.stereo) {
        case StereoMode::ClipShift: state.viewport(whole_target(ctx.frame)); break;
        case StereoMode::ViewportIndex: state.viewport_indexed(0, whole_target(ctx.frame)); break;
        case StereoMode::TwoPass: state.viewport(eye_viewport(ctx.frame, ctx.eye)); break;
    }
    state.vertex_array(ctx.programs.empty_vao.get());
}

int instances_of(const DrawContext& ctx) { return ctx.frame.stereo == StereoMode::TwoPass ? 1 : 2; }

void submit_queued(const DrawContext& ctx, const LevelView& view, const SceneDraw& draw, GLuint vertex_array) {
    IndirectDraws& queue = ctx.scratch.indirect;
    if (queue.pending.empty()) return;
    bind_draw(ctx, view, draw);
    if (vertex_array != 0) ctx.state.vertex_array(vertex_array);
    for (const IndirectDraw& d : queue.pending)
        ctx.scratch.stats.triangles += static_cast<long>(d.count / 3) * static_cast<long>(d.instance_count);
    ctx.scratch.stats.draw_calls += submit_indirect(ctx.state, queue);
}

void draw_range(const DrawContext& ctx, const LevelView& view, const SceneDraw& draw, const scene::IndexRange& range) {
    assert(ctx.scratch.indirect.pending.empty());  // nothing queued for another draw
    queue_range(ctx.scratch.indirect, range, instances_of(ctx));
    submit_queued(ctx, view, draw);
}

void draw_full_target(const DrawContext& ctx, const LevelView& view, const TargetDraw& draw, int quads) {
    bind_draw(ctx, view, draw);
    if (quads > 0)
        glDrawArraysInstanced(GL_TRIANGLES, 0, 6, quads);
    else
        glDrawArrays(GL_TRIANGLES, 0, 3);
    ctx.scratch.stats.draw_calls += 1;
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
    x0 = std::max(x0, 0);
    y0 = std::max(y0, 0);
    x1 = std::min(x1, 2 * w);
    y1 = std::min(y1, h);
    return {x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
}

Scissor level_scissor(const DrawContext& ctx, const LevelView& view) {
    if (!ctx.frame.cull_portals || !view.through_portal) return std::nullopt;
    // The eyes' rectangles are those of the portal the view came through,
    // and an eye is active where the portal was seen: the portal's scissor.
    return scissor_of(ctx, {view.eyes[0].rect, view.eyes[1].rect}, view);
}

Scissor portal_scissor(const DrawContext& ctx, const LevelView& view, const std::array<NdcRect, 2>& rects) {
    if (!ctx.frame.cull_portals) return std::nullopt;
    return scissor_of(ctx, rects, view);
}

namespace {

// An eye's rectangle as the draw's clip distances take it.
NdcRect draw_rect(const DrawContext& ctx, const EyeView& ev, const NdcRect& rect) {
    NdcRect nr = ev.active ? rect : NdcRect::none();
    if (nr.empty()) return nr;
    // One pixel of margin keeps float rounding from trimming a pixel whose
    // centre the portal covers; the stencil bounds the rest. Never past the
    // eye's own image: in clip-shift mode x = ±1 is the seam between the two
    // eyes. Without culling, the whole image: only the stencil bounds the draw.
    return ctx.frame.cull_portals ? intersect(widened(nr, 1.0, ctx.frame.eye_width, ctx.frame.eye_height), NdcRect{})
                                  : NdcRect{};
}

// Both eyes' view-projections, draw rectangles and clip planes, as the
// shaders take them.
struct EyeUniforms {
    float vp[2][16];
    float rect[2][4];
    float plane[2][4];
};

// Eye e's view-projection of `model`'s coordinates and its draw rectangle.
void set_eye_matrix_and_rect(const DrawContext& ctx, const EyeView& ev, const math::dmat4& model, const NdcRect& in,
                             EyeUniforms& u, int e) {
    const math::dmat4 view_proj = ev.view_proj * model;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) u.vp[e][c * 4 + r] = static_cast<float>(view_proj[c][r]);
    const NdcRect nr = draw_rect(ctx, ev, in);
    u.rect[e][0] = static_cast<float>(nr.x0);
    u.rect[e][1] = static_cast<float>(nr.y0);
    u.rect[e][2] = static_cast<float>(nr.x1);
    u.rect[e][3] = static_cast<float>(nr.y1);
}

void upload_eye_uniforms(const SceneProgram& program, const EyeUniforms& u) {
    const GLuint p = program.program.get();
    glProgramUniformMatrix4fv(p, program.view_proj, 2, GL_FALSE, &u.vp[0][0]);
    glProgramUniform4fv(p, program.eye_rect, 2, &u.rect[0][0]);
    glProgramUniform4fv(p, program.clip_plane, 2, &u.plane[0][0]);
}

}  // namespace

void set_model_uniforms(const DrawContext& ctx, const LevelView& view, const SceneProgram& program,
                        const std::array<NdcRect, 2>& rects, const math::dmat4& model,
                        const glm::vec3& checker_offset) {
    EyeUniforms u;
    for (int e = 0; e < 2; ++e) {
        const EyeView& ev = view.eyes[e];
        set_eye_matrix_and_rect(ctx, ev, model, rects[e], u, e);
        // The plane in the model's coordinates: dot(plane, model · p).
        const math::dvec4 model_plane = glm::transpose(model) * ev.clip_plane;
        for (int c = 0; c < 4; ++c) u.plane[e][c] = static_cast<float>(model_plane[c]);
    }
    upload_eye_uniforms(program, u);
    glProgramUniform3fv(program.program.get(), program.checker_offset, 1, &checker_offset[0]);
}

void set_eye_uniforms(const DrawContext& ctx, const LevelView& view, const SceneProgram& program,
                      const std::array<NdcRect, 2>& rects) {
    // The cell's vertices are relative to its origin: the move to layout
    // coordinates is folded into the matrices and planes here, in double.
    const scene::CellOrigin& cell_origin = ctx.scene.cell_origins[static_cast<size_t>(view.cell)];
    const math::dvec3 origin = cell_origin.origin;
    const math::dmat4 from_cell = glm::translate(math::dmat4(1.0), origin);
    EyeUniforms u;
    for (int e = 0; e < 2; ++e) {
        const EyeView& ev = view.eyes[e];
        set_eye_matrix_and_rect(ctx, ev, from_cell, rects[e], u, e);
        const math::dvec4 cell_plane(math::dvec3(ev.clip_plane),
                                     ev.clip_plane.w + glm::dot(math::dvec3(ev.clip_plane), origin));
        for (int c = 0; c < 4; ++c) u.plane[e][c] = static_cast<float>(cell_plane[c]);
    }
    upload_eye_uniforms(program, u);
    glProgramUniform3fv(program.program.get(), program.checker_offset, 1, &cell_origin.checker_offset[0]);
    // The cell's own geometry hides the inside of its volumes.
    if (program.volume_count >= 0) set_volume_uniforms(ctx, view, program, from_cell, -1);
}

void set_cell_id(const SceneProgram& program, unsigned id, bool unshaded) {
    const GLuint p = program.program.get();
    glProgramUniform1ui(p, program.cell_id, id);
    glProgramUniform1i(p, program.unshaded, unshaded ? 1 : 0);
}

void set_volume_uniforms(const DrawContext& ctx, const LevelView& view, const SceneProgram& program,
                         const math::dmat4& to_cell, int inside) {
    if (program.volume_count < 0) return;
    const auto cell = static_cast<size_t>(view.cell);
    const std::vector<VolumeBox>& volumes = ctx.scene.volumes[cell];
    const math::dvec3 origin = ctx.scene.cell_origins[cell].origin;
    const glm::mat4 m(glm::translate(math::dmat4(1.0), -origin) * to_cell);
    const glm::vec3 tint = inside >= 0 ? glm::vec3(volumes[static_cast<size_t>(inside)].tint) : glm::vec3(1.0f);
    const GLuint p = program.program.get();
    glProgramUniformMatrix4fv(p, program.to_volume_space, 1, GL_FALSE, &m[0][0]);
    glProgramUniform1i(p, program.volume_first, ctx.scene.volume_first[cell]);
    glProgramUniform1i(p, program.volume_count, static_cast<int>(volumes.size()));
    glProgramUniform1i(p, program.volume_inside, inside);
    glProgramUniform3fv(p, program.volume_tint, 1, &tint[0]);
}

}  // namespace impossible::render
