#include "render/renderer.hpp"
#include "render/web_profile.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "math/eyes.hpp"
#include "math/projection.hpp"
#include "math/view_limits.hpp"
#include "render/lights/shadow_regions.hpp"
#include "render/objects/frame_objects.hpp"
#include "render/portals/passes.hpp"
#include "render/portals/portal_glass.hpp"
#include "render/portals/portal_recursion.hpp"
#include "render/portals/portal_texture.hpp"
#include "render/portals/technique_zclear.hpp"
#include "render/renderer_parts.hpp"

namespace impossible::render {
namespace {

// Every scene program of `mode` draws with the frame's exposure: 2^EV, the
// view's or the layout's (docs/lighting.md, "Exposure").
void set_exposure(const Programs& programs, StereoMode mode, double ev) {
    const float scale = static_cast<float>(std::exp2(ev));
    const auto set = [scale](const SceneProgram* p) {
        if (p && p->exposure >= 0) glProgramUniform1f(p->program.get(), p->exposure, scale);
    };
    const int m = mode_index(mode);
    set(programs.scene[m] ? &*programs.scene[m] : nullptr);
    set(programs.material[m] ? &*programs.material[m] : nullptr);
    for (const auto& entry : programs.variants[m]) set(&entry.second);
}

// What a frame needs beyond the default program: its target, its stereo
// mode's programs, the light images of its light depth and, for
// render-to-texture portals, their program and targets.
Result<void> prepare_frame(RendererParts& parts, const FrameDesc& frame) {
    if (Result<void> possible = web_profile_check(frame); !possible) return possible;
    // Refused before any buffer is made (math/view_limits.hpp).
    const long long samples = 2LL * frame.eye_width * frame.eye_height * frame.samples;
    if (samples > math::limits::kMaxFrameSamples)
        return Error{"{size} " + std::to_string(frame.eye_width) + "x" + std::to_string(frame.eye_height) +
                     " with {samples} " + std::to_string(frame.samples) + " makes " + std::to_string(samples) +
                     " samples a frame, more than the renderer's bound of " +
                     std::to_string(math::limits::kMaxFrameSamples) + " (2 x 8192 x 8192; docs/bounded-work.md)"};
    const SceneData& r = parts.scene;
    Programs& programs = *parts.programs;
    FrameTargets& targets = parts.targets;
    if (Result<void> made = ensure_frame_target(targets, 2 * frame.eye_width, frame.eye_height, frame.depth); !made)
        return made;
    if (Result<void> made = ensure_scene_program(programs, frame.stereo, false); !made) return made;
    if (r.has_materials)
        if (Result<void> made = ensure_scene_program(programs, frame.stereo, true); !made) return made;
    ensure_lights(parts.lights.buffers, r, frame);  // before the variants: which kind of light buffers
    ensure_light_cache(parts.lights.buffers, r, frame);
    const VariantNeeds needs{
        .objects = !r.object_set.props.empty() || frame.hands.has_value(),
        .volumes = r.has_volumes,
        .lit = r.lighting.lit,
        .lights_ubo = parts.lights.buffers.ubo,
        .lights_naive = r.lighting.lit && frame.naive_lights,
        .materials = r.has_materials,
        .light_loops = r.lighting.lit
                           ? light_loops_needed(parts.lights.buffers, frame.shadows && frame.shadow_map_size > 0,
                                                frame.split_light_draws && frame.cull_portals)
                           : 0u,
        .light_cache = r.lighting.lit && parts.lights.buffers.cache.built};
    if (Result<void> made = ensure_variants(programs, frame.stereo, needs); !made) return made;
    set_exposure(programs, frame.stereo, frame.exposure.value_or(r.exposure));
    if (Result<void> made = ensure_multisampled(programs, targets, frame); !made) return made;
    if (Result<void> made = prepare_hidden_mask(targets.hidden_mask, frame, frame.samples); !made) return made;
    if (r.has_windows) {
        if (Result<void> made = prepare_window_blend(programs, false); !made) return made;
        if (frame.samples > 1)
            if (Result<void> made = prepare_window_blend(programs, true); !made) return made;
    }
    if (frame.z_clear)
        if (Result<void> ok = check_zclear(r, frame); !ok) return ok;
    if (frame.portal_texture_scale <= 0.0) return {};
    if (frame.stereo != StereoMode::ClipShift) return Error{"render-to-texture portals need {stereo} clip-shift"};
    if (!programs.portal_texture) {
        Result<SceneProgram> built = build_portal_texture_program();
        if (!built) return built;
        programs.portal_texture = std::move(*built);
    }
    if (r.has_volumes && !programs.portal_texture_volumes) {
        Result<SceneProgram> built = build_portal_texture_program(true);
        if (!built) return built;
        programs.portal_texture_volumes = std::move(*built);
    }
    return ensure_portal_textures(r, targets, frame);
}

// Per-eye views of the head's room at level 0, restricted to `eye_mask`.
LevelView root_view(const FrameDesc& frame, const std::array<math::dmat4, 2>& projections, unsigned eye_mask) {
    LevelView view;
    view.cell = frame.room;
    const std::array<math::Eye, 2> eyes = math::eyes_of(frame);
    for (int e = 0; e < 2; ++e) {
        view.eyes[e].active = (eye_mask >> e) & 1u;
        view.eyes[e].eye = eyes[e];
        view.eyes[e].view_proj = projections[e] * math::view_matrix(eyes[e]);
    }
    return view;
}

// Each eye's projection: one symmetric frustum for both, or each eye's
// optics (math::eye_frustum, as the tracer's).
std::array<math::dmat4, 2> projections_of(const FrameDesc& frame) {
    std::array<math::dmat4, 2> out;
    for (int e = 0; e < 2; ++e) {
        math::Frustum frustum = math::eye_frustum(frame, e);
        frustum.near = near_distance(frame);
        out[static_cast<size_t>(e)] = frame.depth == DepthMode::ReversedZ
                                          ? math::perspective_reversed_z(frustum)
                                          : math::perspective_standard(frustum, frame.far);
    }
    return out;
}

// Both eyes' views of the frame, as the stereo mode draws them.
void draw_stereo(const DrawContext& ctx) {
    const FrameDesc& frame = ctx.frame;
    const auto draw_root = frame.z_clear ? draw_zclear : draw_level;
    if (frame.stereo != StereoMode::TwoPass) {
        draw_root(ctx, root_view(frame, ctx.projections, 3u));
        return;
    }
    const std::map<unsigned, SceneProgram>& variants = ctx.programs.variants[mode_index(StereoMode::TwoPass)];
    for (int e = 0; e < 2; ++e) {
        glProgramUniform1i(ctx.scene_program.program.get(), ctx.scene_program.single_eye, e);
        if (ctx.material_program)
            glProgramUniform1i(ctx.material_program->program.get(), ctx.material_program->single_eye, e);
        for (const auto& entry : variants) {  // no structured binding: glProgramUniform1i is a lambda on the web
            const SceneProgram& variant = entry.second;
            glProgramUniform1i(variant.program.get(), variant.single_eye, e);
        }
        DrawContext one_eye = ctx;
        one_eye.eye = e;
        draw_root(one_eye, root_view(frame, ctx.projections, 1u << e));
    }
}

// Whether the frame draws from the light cache, and its atlas bound: the
// cache knows the still props' shadows only.
void bind_light_cache(gl::StateCache& state, LightBuffers& buffers, const FrameDesc& frame,
                      const FrameObjects& objects) {
    const LightCacheGpu& cache = buffers.cache;
    buffers.use_cache = cache.built && cache.map_size == cache_map_size(frame) && frame.light_cache &&
                        !frame.naive_lights && objects.instances.empty();
    if (!buffers.use_cache) return;
    state.texture(kLightCacheUnit, cache.corners.get());
    state.texture(kLightEdgesUnit, cache.edges.get());
}

// A frame drawn, and read back into `image` unless it is null.
Result<void> draw_frame(RendererParts& parts, const FrameDesc& frame, FrameStats* stats_out, image::Image* image) {
    const SceneData& r = parts.scene;
    assert(frame.room >= 0 && static_cast<size_t>(frame.room) < r.cells.size());
    if (Result<void> ready = prepare_frame(parts, frame); !ready) return ready;
    gl::StateCache& state = *parts.state;
    LightState& lights = parts.lights;
    FrameScratch& scratch = parts.scratch;
    scratch.begin_frame();
    place_frame_objects(r, frame, scratch.objects, parts.kept.prop_walks.get());
    // Bound for the frame: another renderer of the context may bind its own.
    if (r.has_volumes) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kVolumeBinding, r.volume_boxes.get());
    // A lit layout's images and the props' shadow maps (drawn again only
    // where their inputs changed).
    if (r.lighting.lit) {
        if (Result<void> shadows = prepare_shadow_maps(lights.shadow_maps, state, r, scratch.objects,
                                                       lights.buffers.rooms, frame, scratch.stats);
            !shadows)
            return shadows;
        lights.buffers.shadow_regions =
            frame_shadow_regions(lights.shadow_maps, r, scratch.objects, lights.buffers.rooms, frame);
        bind_light_buffers(&lights.buffers);
        bind_light_cache(state, lights.buffers, frame, scratch.objects);
    }
    const Target& target = drawing_target(parts.targets, frame);
    clear_target(state, target, stencil_level(frame.max_depth, 0));
    draw_hidden_mask(state, target, parts.targets.hidden_mask, scratch.stats);

    FrameProfiler profiler;
    const Programs& programs = *parts.programs;
    const int mode = mode_index(frame.stereo);
    const DrawContext ctx{.state = state,
                          .scene = r,
                          .programs = programs,
                          .lights = lights.buffers,
                          .frame = frame,
                          .scene_program = *programs.scene[mode],
                          .material_program = r.has_materials ? &*programs.material[mode] : nullptr,
                          .target = target,
                          .targets = parts.targets,
                          .projections = projections_of(frame),
                          .eye = -1,
                          .profiler = frame.profile ? &profiler : nullptr,
                          .scratch = scratch};
    draw_stereo(ctx);
    resolve_multisampled(state, programs, parts.targets, frame);
    if (image) *image = read_target(state, parts.targets.target);
    // Nothing of this renderer stays bound: the cache is the context's, and
    // a name GL reuses after this renderer's objects are deleted must not
    // look bound already.
    state.release_bindings();
    if (r.has_volumes) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kVolumeBinding, 0);
    if (r.lighting.lit) {
        bind_light_buffers(nullptr);
        unbind_shadow_maps();
    }
    if (frame.profile) profiler.collect(scratch.stats);
    if (stats_out) *stats_out = std::move(scratch.stats);
    return {};
}

}  // namespace

SharedPrograms make_shared_programs() { return std::make_shared<Programs>(); }

Result<Renderer> Renderer::create(gl::StateCache& state, const scene::Scene& scene, SharedPrograms programs_in) {
    auto parts = std::make_unique<RendererParts>();
    parts->state = &state;
    copy_scene(parts->scene, scene);
    // RendererParts stays where it is: the walks keep a pointer to the set.
    parts->kept.prop_walks = std::make_unique<walk::PropWalks>(parts->scene.object_set);
    parts->programs = programs_in ? std::move(programs_in) : make_shared_programs();
    Programs& programs = *parts->programs;
    if (!programs.empty_vao) {  // the first renderer of these programs
        Result<ClearDepthProgram> clear = build_clear_depth_program();
        if (!clear) return clear;
        programs.clear_depth = std::move(*clear);
        programs.empty_vao = gl::create_vertex_array();
    }
    if (Result<void> made = ensure_scene_program(programs, StereoMode::ClipShift, false); !made) return made;
    return Renderer(std::move(parts));
}

Renderer::Renderer(std::unique_ptr<RendererParts> parts) : parts_(std::move(parts)) {}
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;
Renderer::~Renderer() = default;

const Target& Renderer::target() const { return parts_->targets.target; }

const SharedPrograms& Renderer::programs() const { return parts_->programs; }

Result<void> Renderer::draw(const FrameDesc& frame, FrameStats* stats_out) {
    FrameDesc adjusted;
    return draw_frame(*parts_, web_profile_fallbacks(frame, adjusted), stats_out, nullptr);
}

Result<RenderedFrame> Renderer::render(const FrameDesc& frame) {
    RenderedFrame out;
    FrameDesc adjusted;
    if (Result<void> drawn = draw_frame(*parts_, web_profile_fallbacks(frame, adjusted), &out.stats, &out.image);
        !drawn)
        return drawn;
    return out;
}

}  // namespace impossible::render
