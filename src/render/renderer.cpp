#include "render/renderer.hpp"

#include <cassert>

#include "math/projection.hpp"
#include "render/passes.hpp"
#include "render/portal_recursion.hpp"
#include "render/renderer_data.hpp"
#include "shading/shading.hpp"

namespace impossible::render {
namespace {

int mode_index(StereoMode mode) {
    const int i = static_cast<int>(mode);
    assert(i >= 0 && i < kStereoModeCount);
    return i;
}

Result<void> ensure_target(RendererData& r, int width, int height, DepthMode depth) {
    if (r.target.width == width && r.target.height == height && r.target.depth == depth && r.target.framebuffer)
        return {};
    Result<Target> made = create_target(width, height, depth);
    if (!made) return Error{made.error()};
    r.target = std::move(*made);
    // The resolve's framebuffers hold the old target's buffers.
    r.multisampling.colour_out = {};
    r.multisampling.ids_out = {};
    return {};
}

Result<void> ensure_program(RendererData& r, StereoMode mode, bool materials) {
    std::optional<SceneProgram>& slot = (materials ? r.material_programs : r.programs)[mode_index(mode)];
    if (slot) return {};
    Result<SceneProgram> built = build_scene_program(mode, materials);
    if (!built) {
        if (mode == StereoMode::ViewportIndex)
            return Error{"stereo mode 'viewport-index' needs GL_ARB_shader_viewport_layer_array: " + built.error()};
        return Error{built.error()};
    }
    slot = std::move(*built);
    return {};
}

// What a frame needs beyond the default program: its target, its stereo
// mode's program and, for render-to-texture portals, their program and targets.
Result<void> prepare_frame(RendererData& r, const FrameDesc& frame) {
    if (Result<void> made = ensure_target(r, 2 * frame.eye_width, frame.eye_height, frame.depth); !made) return made;
    if (Result<void> made = ensure_program(r, frame.stereo, false); !made) return made;
    if (r.has_materials)
        if (Result<void> made = ensure_program(r, frame.stereo, true); !made) return made;
    if (Result<void> made = ensure_multisampled(r, frame); !made) return made;
    if (r.has_windows) {
        if (Result<void> made = prepare_window_blend(r, false); !made) return made;
        if (frame.samples > 1)
            if (Result<void> made = prepare_window_blend(r, true); !made) return made;
    }
    if (frame.portal_texture_scale <= 0.0) return {};
    if (frame.stereo != StereoMode::ClipShift) return Error{"render-to-texture portals need --stereo clip-shift"};
    if (!r.portal_texture_program) {
        Result<SceneProgram> built = build_portal_texture_program();
        if (!built) return Error{built.error()};
        r.portal_texture_program = std::move(*built);
    }
    return ensure_portal_textures(r, frame);
}

// Per-eye views of the head's room at level 0, restricted to `eye_mask`.
LevelView root_view(const FrameDesc& frame, const math::dmat4& projection, unsigned eye_mask) {
    LevelView view;
    view.cell = frame.room;
    const std::array<math::Eye, 2> eyes = math::eyes_of(frame.head, frame.ipd);
    for (int e = 0; e < 2; ++e) {
        view.eyes[e].active = (eye_mask >> e) & 1u;
        view.eyes[e].eye = eyes[e];
        view.eyes[e].view_proj = projection * math::view_matrix(eyes[e]);
    }
    return view;
}

math::dmat4 projection_of(const FrameDesc& frame) {
    math::Frustum frustum;
    frustum.fov_y_deg = frame.fov_y_deg;
    frustum.aspect = static_cast<double>(frame.eye_width) / frame.eye_height;
    frustum.near = near_distance(frame);
    return frame.depth == DepthMode::ReversedZ ? math::perspective_reversed_z(frustum)
                                               : math::perspective_standard(frustum, frame.far);
}

// Both eyes' views of the frame into the bound target, as the stereo mode draws them.
void draw_stereo(DrawContext& ctx) {
    const FrameDesc& frame = ctx.frame;
    gl::StateCache& state = *ctx.renderer.state;
    const gl::WindowRect whole{0, 0, 2 * frame.eye_width, frame.eye_height};
    switch (frame.stereo) {
        case StereoMode::ClipShift:
            state.viewport(whole);
            draw_level(ctx, root_view(frame, ctx.projection, 3u));
            break;
        case StereoMode::ViewportIndex:
            state.viewport_indexed(0, {0, 0, frame.eye_width, frame.eye_height});
            state.viewport_indexed(1, {frame.eye_width, 0, frame.eye_width, frame.eye_height});
            draw_level(ctx, root_view(frame, ctx.projection, 3u));
            state.viewport(whole);
            break;
        case StereoMode::TwoPass:
            for (int e = 0; e < 2; ++e) {
                state.viewport({e * frame.eye_width, 0, frame.eye_width, frame.eye_height});
                glProgramUniform1i(ctx.program.program.get(), ctx.program.single_eye, e);
                if (ctx.material_program)
                    glProgramUniform1i(ctx.material_program->program.get(), ctx.material_program->single_eye, e);
                draw_level(ctx, root_view(frame, ctx.projection, 1u << e));
            }
            state.viewport(whole);
            break;
    }
}

}  // namespace

void clear_target(RendererData& r, const Target& target, int stencil) {
    r.state->apply(kClearState, 0);
    r.state->no_scissor();
    const glm::dvec3 bg = shading::kBackgroundColor;
    const GLfloat color[4] = {static_cast<GLfloat>(bg.r), static_cast<GLfloat>(bg.g),
                              static_cast<GLfloat>(bg.b), 1.0f};
    const GLuint id[4] = {0, 0, 0, 0};
    const GLuint fb = target.framebuffer.get();
    glClearNamedFramebufferfv(fb, GL_COLOR, 0, color);
    glClearNamedFramebufferuiv(fb, GL_COLOR, 1, id);
    glClearNamedFramebufferfi(fb, GL_DEPTH_STENCIL, 0, target.depth == DepthMode::ReversedZ ? 0.0f : 1.0f,
                              stencil);
}

Result<Renderer> Renderer::create(gl::StateCache& state, const scene::Scene& scene) {
    auto r = std::make_unique<RendererData>();
    r->state = &state;
    r->cells = scene.batches;
    r->objects = scene.objects;
    for (const auto& cell : scene.batches)
        for (const scene::DrawBatch& b : cell) r->has_materials = r->has_materials || b.texture >= 0 || b.alpha_cutoff >= 0.0f;
    r->frames = scene.frames;
    r->links = scene.links;
    r->portals = scene.portal_info;
    r->portal_meshes = scene.portals;
    for (const scene::PortalInfo& p : scene.portal_info)
        r->has_windows = r->has_windows || p.kind == layout::PortalKind::Window;
    r->gpu = upload_scene(scene);
    r->empty_vao = gl::create_vertex_array();
    Result<ClearDepthProgram> clear = build_clear_depth_program();
    if (!clear) return Error{clear.error()};
    r->clear_depth = std::move(*clear);
    if (Result<void> made = ensure_program(*r, StereoMode::ClipShift, false); !made) return Error{made.error()};
    return Renderer(std::move(r));
}

Renderer::Renderer(std::unique_ptr<RendererData> data) : data_(std::move(data)) {}
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;
Renderer::~Renderer() = default;

const Target& Renderer::target() const { return data_->target; }

Result<void> Renderer::draw(const FrameDesc& frame, FrameStats* stats_out) {
    RendererData& r = *data_;
    assert(frame.room >= 0 && static_cast<size_t>(frame.room) < r.cells.size());
    if (Result<void> ready = prepare_frame(r, frame); !ready) return ready;
    const SceneProgram& program = *r.programs[mode_index(frame.stereo)];
    gl::StateCache& state = *r.state;

    Target& target = drawing_target(r, frame);
    state.draw_framebuffer(target.framebuffer.get());
    // Reversed-Z: depth 1 at the near plane, 0 at infinity, in a float buffer.
    state.clip_control(frame.depth == DepthMode::ReversedZ ? GL_ZERO_TO_ONE : GL_NEGATIVE_ONE_TO_ONE);
    clear_target(r, target, 0);
    state.program(program.program.get());
    state.vertex_array(r.gpu.vao.get());
    begin_indirect_frame(r.indirect);

    FrameStats stats;
    FrameProfiler profiler;
    DrawContext ctx{r, program, frame, stats, projection_of(frame), frame.profile ? &profiler : nullptr};
    if (r.has_materials) ctx.material_program = &*r.material_programs[mode_index(frame.stereo)];
    ctx.target = &target;
    draw_stereo(ctx);
    resolve_multisampled(r, frame);
    unbind_indirect();
    // Nothing of this renderer stays bound: the cache is the context's, and
    // a name GL reuses after this renderer's objects are deleted must not
    // look bound already.
    state.vertex_array(0);
    state.program(0);
    state.draw_framebuffer(0);
    if (frame.profile) profiler.collect(stats);
    if (stats_out) *stats_out = std::move(stats);
    return {};
}

Result<RenderedFrame> Renderer::render(const FrameDesc& frame) {
    RenderedFrame out;
    if (Result<void> drawn = draw(frame, &out.stats); !drawn) return Error{drawn.error()};
    out.image = read_target(data_->target);
    return out;
}

}  // namespace impossible::render
