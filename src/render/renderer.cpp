#include "render/renderer.hpp"

#include "math/projection.hpp"
#include "render/portal_recursion.hpp"
#include "scene/shading.hpp"

namespace impossible::render {
namespace {

int mode_index(StereoMode mode) { return static_cast<int>(mode); }

std::string ensure_target(Renderer& r, int width, int height, DepthMode depth) {
    if (r.target.width == width && r.target.height == height && r.target.depth == depth && r.target.framebuffer)
        return {};
    TargetResult made = create_target(width, height, depth);
    if (!made.error.empty()) return made.error;
    r.target = std::move(made.target);
    return {};
}

std::string ensure_program(Renderer& r, StereoMode mode) {
    std::optional<SceneProgram>& slot = r.programs[mode_index(mode)];
    if (slot) return {};
    SceneProgramResult built = build_scene_program(mode);
    if (!built.error.empty()) {
        if (mode == StereoMode::ViewportIndex)
            return "stereo mode 'viewport-index' needs GL_ARB_shader_viewport_layer_array: " + built.error;
        return built.error;
    }
    slot = std::move(built.program);
    return {};
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

}  // namespace

void clear_target(Renderer& r, const Target& target, int stencil) {
    // Clears obey the write masks and the scissor: all writes on, no scissor.
    r.state.apply(gl::PassState{}, 0);
    r.state.no_scissor();
    const glm::dvec3 bg = scene::kBackgroundColor;
    const GLfloat color[4] = {static_cast<GLfloat>(bg.r), static_cast<GLfloat>(bg.g),
                              static_cast<GLfloat>(bg.b), 1.0f};
    const GLuint id[4] = {0, 0, 0, 0};
    const GLuint fb = target.framebuffer.get();
    glClearNamedFramebufferfv(fb, GL_COLOR, 0, color);
    glClearNamedFramebufferuiv(fb, GL_COLOR, 1, id);
    glClearNamedFramebufferfi(fb, GL_DEPTH_STENCIL, 0, target.depth == DepthMode::ReversedZ ? 0.0f : 1.0f,
                              stencil);
}

RendererResult create_renderer(const layout::Layout& layout, const scene::Scene& scene) {
    RendererResult out;
    auto r = std::make_unique<Renderer>();
    r->layout = layout;
    r->scene = scene;
    r->portals_of_room.resize(layout.rooms.size());
    for (size_t i = 0; i < layout.portals.size(); ++i) {
        const layout::Portal& a = layout.portals[i];
        r->transfer.push_back(math::transfer_matrix(a.rect, layout.portals[a.target].rect));
        r->portals_of_room[a.room].push_back(static_cast<int>(i));
    }
    r->gpu = upload_scene(scene);
    r->empty_vao = gl::create_vertex_array();
    ClearDepthProgramResult clear = build_clear_depth_program();
    if (!clear.error.empty()) {
        out.error = clear.error;
        return out;
    }
    r->clear_depth = std::move(clear.program);
    if (std::string e = ensure_program(*r, StereoMode::ClipShift); !e.empty()) {
        out.error = e;
        return out;
    }
    for (int i = 0; i < 5; ++i) glEnable(GL_CLIP_DISTANCE0 + i);
    glFrontFace(GL_CCW);
    r->state.invalidate();
    out.renderer = std::move(r);
    return out;
}

std::string draw_frame(Renderer& r, const FrameDesc& frame, FrameStats* stats_out) {
    const int width = 2 * frame.eye_width, height = frame.eye_height;
    if (std::string e = ensure_target(r, width, height, frame.depth); !e.empty()) return e;
    if (std::string e = ensure_program(r, frame.stereo); !e.empty()) return e;
    if (frame.portal_texture_scale > 0.0) {
        if (frame.stereo != StereoMode::ClipShift) return "render-to-texture portals need --stereo clip-shift";
        if (!r.portal_texture_program) {
            SceneProgramResult built = build_portal_texture_program();
            if (!built.error.empty()) return built.error;
            r.portal_texture_program = std::move(built.program);
        }
    }
    const SceneProgram& program = *r.programs[mode_index(frame.stereo)];

    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, r.target.framebuffer.get());
    // Reversed-Z: depth 1 at the near plane, 0 at infinity, in a float buffer.
    const bool reversed_z = frame.depth == DepthMode::ReversedZ;
    glClipControl(GL_LOWER_LEFT, reversed_z ? GL_ZERO_TO_ONE : GL_NEGATIVE_ONE_TO_ONE);
    // Other code (a second renderer, the preview's overlays) may have used the
    // context since the last frame: the cache re-sends every state once.
    r.state.invalidate();
    clear_target(r, r.target, 0);
    glUseProgram(program.program.get());
    glBindVertexArray(r.gpu.vao.get());

    math::Frustum frustum;
    frustum.fov_y_deg = frame.fov_y_deg;
    frustum.aspect = static_cast<double>(frame.eye_width) / frame.eye_height;
    frustum.near = frame.near;
    FrameStats stats;
    FrameProfiler profiler;
    DrawContext ctx{r, program, frame, stats,
                    reversed_z ? math::perspective_reversed_z(frustum) : math::perspective_standard(frustum, frame.far),
                    frame.profile ? &profiler : nullptr};

    const float w = static_cast<float>(frame.eye_width), h = static_cast<float>(frame.eye_height);
    switch (frame.stereo) {
        case StereoMode::ClipShift:
            glViewport(0, 0, width, height);
            draw_level(ctx, root_view(frame, ctx.projection, 3u));
            break;
        case StereoMode::ViewportIndex:
            glViewportIndexedf(0, 0.0f, 0.0f, w, h);
            glViewportIndexedf(1, w, 0.0f, w, h);
            draw_level(ctx, root_view(frame, ctx.projection, 3u));
            glViewport(0, 0, width, height);
            break;
        case StereoMode::TwoPass:
            for (int e = 0; e < 2; ++e) {
                glViewport(e * frame.eye_width, 0, frame.eye_width, frame.eye_height);
                glProgramUniform1i(program.program.get(), program.single_eye, e);
                draw_level(ctx, root_view(frame, ctx.projection, 1u << e));
            }
            glViewport(0, 0, width, height);
            break;
    }
    glBindVertexArray(0);
    glUseProgram(0);
    if (frame.profile) collect_profile(profiler, stats);
    if (stats_out) *stats_out = std::move(stats);
    return {};
}

FrameResult render_frame(Renderer& r, const FrameDesc& frame) {
    FrameResult out;
    out.error = draw_frame(r, frame, &out.stats);
    if (out.error.empty()) out.image = read_target(r.target);
    return out;
}

}  // namespace impossible::render
