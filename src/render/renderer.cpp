#include "render/renderer.hpp"

#include <algorithm>
#include <cassert>

#include "math/projection.hpp"
#include "render/objects/frame_objects.hpp"
#include "render/portals/passes.hpp"
#include "render/portals/portal_glass.hpp"
#include "render/portals/portal_recursion.hpp"
#include "render/portals/portal_texture.hpp"
#include "render/portals/technique_zclear.hpp"
#include "render/renderer_data.hpp"
#include "shading/shading.hpp"

namespace impossible::render {
namespace {

int mode_index(StereoMode mode) {
    const int i = static_cast<int>(mode);
    assert(i >= 0 && i < kStereoModeCount);
    return i;
}

Result<void> ensure_target(FrameTargets& targets, int width, int height, DepthMode depth) {
    Target& t = targets.target;
    if (t.width == width && t.height == height && t.depth == depth && t.framebuffer) return {};
    Result<Target> made = create_target(width, height, depth);
    if (!made) return made;
    t = std::move(*made);
    // The resolve's framebuffers hold the old target's buffers.
    targets.multisampling.colour_out = {};
    targets.multisampling.ids_out = {};
    return {};
}

Result<void> ensure_program(Programs& programs, StereoMode mode, bool materials) {
    std::optional<SceneProgram>& slot = (materials ? programs.material : programs.scene)[mode_index(mode)];
    if (slot) return {};
    Result<SceneProgram> built = build_scene_program(mode, materials);
    if (!built) {
        if (mode == StereoMode::ViewportIndex)
            return Error{"stereo mode 'viewport-index' needs GL_ARB_shader_viewport_layer_array: " + built.error()};
        return built;
    }
    slot = std::move(*built);
    return {};
}

// The variants with object cuts, volumes or lights (scene_program.hpp) that
// a frame of `mode` may draw with.
Result<void> ensure_variants(RendererData& r, StereoMode mode, bool objects) {
    const bool volumes = r.has_volumes;
    for (unsigned flags = 0; flags < kSceneVariantCount; ++flags) {
        if ((flags & (kObjectCuts | kVolumes | kLights)) == 0u) continue;
        if (((flags & kObjectCuts) && !objects) || ((flags & kVolumes) && !volumes)) continue;
        if ((flags & kLights) && !r.lit) continue;
        // The light buffers' kind for the frame's light depth (ensure_lights).
        if ((flags & kLightsUbo) && (!(flags & kLights) || !r.lights.ubo)) continue;
        if ((flags & kLights) && !(flags & kLightsUbo) && r.lights.ubo) continue;
        if ((flags & kMaterials) && !r.has_materials) continue;
        std::optional<SceneProgram>& slot = r.programs.variants[mode_index(mode)][flags];
        if (slot) continue;
        Result<SceneProgram> built = build_scene_variant(mode, flags);
        if (!built) return built;
        slot = std::move(*built);
    }
    return {};
}

// A lit layout's light images at the frame's light depth on the GPU: the
// scene's, or made for View::light_depth when it differs, and kept until a
// frame asks for another depth.
void ensure_lights(RendererData& r, const FrameDesc& frame) {
    if (!r.lit) return;
    const int depth = std::min(frame.light_depth.value_or(r.scene_light_depth), r.max_light_depth);
    if (r.lights.depth == depth) return;
    if (depth == r.scene_light_depth) {
        r.lights = upload_light_images(r.scene_room_lights, *r.lit_layout, r.cell_origins, depth);
        return;
    }
    const std::vector<lights::RoomLights> rooms = lights::light_images(*r.lit_layout, r.links, depth);
    r.lights = upload_light_images(rooms, *r.lit_layout, r.cell_origins, depth);
}

// What a frame needs beyond the default program: its target, its stereo
// mode's programs and, for render-to-texture portals, their program and targets.
Result<void> prepare_frame(RendererData& r, FrameTargets& targets, const FrameDesc& frame) {
    Programs& programs = r.programs;
    if (Result<void> made = ensure_target(targets, 2 * frame.eye_width, frame.eye_height, frame.depth); !made)
        return made;
    if (Result<void> made = ensure_program(programs, frame.stereo, false); !made) return made;
    if (r.has_materials)
        if (Result<void> made = ensure_program(programs, frame.stereo, true); !made) return made;
    const bool objects = !r.object_set.props.empty() || frame.hands.has_value();
    ensure_lights(r, frame);  // before the variants: which kind of light buffers
    if (Result<void> made = ensure_variants(r, frame.stereo, objects); !made) return made;
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
    if (frame.stereo != StereoMode::ClipShift) return Error{"render-to-texture portals need --stereo clip-shift"};
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
    const std::array<math::Eye, 2> eyes = math::eyes_of(frame.head, frame.ipd);
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
    const std::optional<SceneProgram>* variants = ctx.renderer.programs.variants[mode_index(StereoMode::TwoPass)];
    for (int e = 0; e < 2; ++e) {
        glProgramUniform1i(ctx.scene_program.program.get(), ctx.scene_program.single_eye, e);
        if (ctx.material_program)
            glProgramUniform1i(ctx.material_program->program.get(), ctx.material_program->single_eye, e);
        for (unsigned flags = 0; flags < kSceneVariantCount; ++flags)
            if (variants[flags]) glProgramUniform1i(variants[flags]->program.get(), variants[flags]->single_eye, e);
        DrawContext one_eye = ctx;
        one_eye.eye = e;
        draw_root(one_eye, root_view(frame, ctx.projections, 1u << e));
    }
}

// A frame drawn, and read back into `image` unless it is null.
Result<void> draw_frame(RendererParts& parts, const FrameDesc& frame, FrameStats* stats_out, image::Image* image) {
    RendererData& r = parts.data;
    assert(frame.room >= 0 && static_cast<size_t>(frame.room) < r.cells.size());
    if (Result<void> ready = prepare_frame(r, parts.targets, frame); !ready) return ready;
    gl::StateCache& state = *r.state;
    FrameScratch& scratch = parts.scratch;
    scratch.begin_frame();
    place_frame_objects(r, frame, scratch.objects, scratch.prop_walks.get());
    // Bound for the frame: another renderer of the context may bind its own.
    if (r.has_volumes) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kVolumeBinding, r.volume_boxes.get());
    // A lit layout's images and the props' shadow maps (drawn again only
    // where their inputs changed).
    if (r.lit) {
        if (Result<void> shadows =
                prepare_shadow_maps(r.shadow_maps, r, scratch.objects, r.lights.rooms, frame, scratch.stats);
            !shadows)
            return shadows;
        bind_light_buffers(&r.lights);
    }
    const Target& target = drawing_target(parts.targets, frame);
    clear_target(state, target, stencil_level(frame.max_depth, 0));
    draw_hidden_mask(state, target, parts.targets.hidden_mask, scratch.stats);

    FrameProfiler profiler;
    const int mode = mode_index(frame.stereo);
    const DrawContext ctx{.renderer = r,
                          .frame = frame,
                          .scene_program = *r.programs.scene[mode],
                          .material_program = r.has_materials ? &*r.programs.material[mode] : nullptr,
                          .target = target,
                          .targets = parts.targets,
                          .projections = projections_of(frame),
                          .eye = -1,
                          .profiler = frame.profile ? &profiler : nullptr,
                          .scratch = scratch};
    draw_stereo(ctx);
    resolve_multisampled(r, parts.targets, frame);
    if (image) *image = read_target(state, parts.targets.target);
    // Nothing of this renderer stays bound: the cache is the context's, and
    // a name GL reuses after this renderer's objects are deleted must not
    // look bound already.
    state.release_bindings();
    if (r.has_volumes) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kVolumeBinding, 0);
    if (r.lit) {
        bind_light_buffers(nullptr);
        unbind_shadow_maps();
    }
    if (frame.profile) profiler.collect(scratch.stats);
    if (stats_out) *stats_out = std::move(scratch.stats);
    return {};
}

void copy_volumes(RendererData& r, const scene::Scene& scene);

// The scene's dynamic objects and volumes, as the renderer draws them.
void copy_objects(RendererData& r, const scene::Scene& scene) {
    r.object_set = scene.object_set;
    r.object_meshes = scene.object_meshes;
    r.prop_mesh.resize(scene.cells.size());
    for (size_t c = 0; c < scene.cells.size() && c < scene.object_set.dynamic.size(); ++c)
        r.prop_mesh[c].assign(scene.object_set.dynamic[c].size(), -1);
    for (size_t i = 0; i < scene.object_set.props.size(); ++i) {
        const walk::DynamicProp& d = scene.object_set.props[i];
        r.prop_mesh[static_cast<size_t>(d.room)][static_cast<size_t>(d.index)] = static_cast<int>(i);
    }
    for (const scene::ObjectMesh& mesh : scene.object_meshes)
        for (const scene::DrawBatch& b : mesh.batches)
            r.has_materials = r.has_materials || b.texture >= 0 || b.alpha_cutoff >= 0.0f;
    copy_volumes(r, scene);
}

// The scene's volumes per room, and all of them in the buffer the VOLUMES
// shaders read.
void copy_volumes(RendererData& r, const scene::Scene& scene) {
    r.volumes.assign(scene.cells.size(), {});
    r.volume_first.assign(scene.cells.size(), 0);
    std::vector<float> boxes;
    for (size_t c = 0; c < scene.volumes.size(); ++c) {
        r.volume_first[c] = static_cast<int>(boxes.size() / 16);
        for (const layout::Volume& v : scene.volumes[c]) {
            VolumeBox box;
            box.center = v.rect.center;
            box.axes = {math::portal_right(v.rect), v.rect.up, v.rect.normal};
            box.half = 0.5 * math::dvec3(v.rect.width, v.rect.height, v.rect.depth);
            box.target = v.target_room;
            box.tint = v.tint;
            r.volumes[c].push_back(box);
            const math::dvec3 centre = box.center - scene.origins[c].origin;
            boxes.insert(boxes.end(), {float(centre.x), float(centre.y), float(centre.z), 0.0f});
            for (int a = 0; a < 3; ++a) {
                const math::dvec3 axis = box.axes[static_cast<size_t>(a)] / box.half[a];
                boxes.insert(boxes.end(), {float(axis.x), float(axis.y), float(axis.z), 0.0f});
            }
        }
    }
    r.has_volumes = !boxes.empty();
    if (!r.has_volumes) return;
    r.volume_boxes = gl::create_buffer();
    glNamedBufferStorage(r.volume_boxes.get(), static_cast<GLsizeiptr>(boxes.size() * sizeof(float)), boxes.data(), 0);
}

}  // namespace

void clear_target(gl::StateCache& state, const Target& target, int stencil) {
    state.apply(kClearState, 0);
    state.no_scissor();
    const glm::dvec3 bg = shading::kBackgroundColor;
    const GLfloat color[4] = {static_cast<GLfloat>(bg.r), static_cast<GLfloat>(bg.g), static_cast<GLfloat>(bg.b), 1.0f};
    const GLuint id[4] = {0, 0, 0, 0};
    const GLuint fb = target.framebuffer.get();
    glClearNamedFramebufferfv(fb, GL_COLOR, 0, color);
    glClearNamedFramebufferuiv(fb, GL_COLOR, 1, id);
    glClearNamedFramebufferfi(fb, GL_DEPTH_STENCIL, 0, target.depth == DepthMode::ReversedZ ? 0.0f : 1.0f, stencil);
}

Result<Renderer> Renderer::create(gl::StateCache& state, const scene::Scene& scene) {
    auto parts = std::make_unique<RendererParts>();
    RendererData& r = parts->data;
    r.state = &state;
    r.cells = scene.batches;
    r.objects = scene.objects;
    for (const auto& cell : scene.batches)
        for (const scene::DrawBatch& b : cell)
            r.has_materials = r.has_materials || b.texture >= 0 || b.alpha_cutoff >= 0.0f;
    copy_objects(r, scene);
    // RendererParts stays where it is: the walks may keep a pointer to the set.
    parts->scratch.prop_walks = std::make_unique<walk::PropWalks>(r.object_set);
    r.cell_origins = scene.origins;
    r.lit = scene.lighting == layout::Lighting::Lights && scene.lit_layout != nullptr;
    if (r.lit) {
        r.scene_light_depth = scene.light_depth;
        r.max_light_depth = scene.max_light_depth;
        r.scene_room_lights = scene.room_lights;
        r.lit_layout = scene.lit_layout;
    }
    r.links = scene.links;
    r.portals = scene.portal_info;
    r.portal_meshes = scene.portals;
    for (const scene::PortalInfo& p : scene.portal_info)
        r.has_windows = r.has_windows || p.kind == layout::PortalKind::Window;
    r.gpu = upload_scene(scene);
    r.empty_vao = gl::create_vertex_array();
    Result<ClearDepthProgram> clear = build_clear_depth_program();
    if (!clear) return clear;
    r.programs.clear_depth = std::move(*clear);
    if (Result<void> made = ensure_program(r.programs, StereoMode::ClipShift, false); !made) return made;
    return Renderer(std::move(parts));
}

Renderer::Renderer(std::unique_ptr<RendererParts> parts) : parts_(std::move(parts)) {}
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;
Renderer::~Renderer() = default;

const Target& Renderer::target() const { return parts_->targets.target; }

Result<void> Renderer::draw(const FrameDesc& frame, FrameStats* stats_out) {
    return draw_frame(*parts_, frame, stats_out, nullptr);
}

Result<RenderedFrame> Renderer::render(const FrameDesc& frame) {
    RenderedFrame out;
    if (Result<void> drawn = draw_frame(*parts_, frame, &out.stats, &out.image); !drawn) return drawn;
    return out;
}

}  // namespace impossible::render
