// Dynamic objects and volume portals in the stencil recursion
// (layout-format.md, "Moving props, hands and crossing objects" and "Volume
// portals"; docs/crossing.md).
//
// The frame's objects are placed once (frame_objects.hpp): instances, each
// a mesh, a cell, a rigid matrix from the mesh's own coordinates and up to
// two door planes that cut it. Every level that draws a cell draws the
// cell's instances after its own batches, each batch one instanced draw for
// both eyes like any other, with the matrix folded into the eyes'
// view-projections and the cuts as two more clip distances (the OBJECT_CUTS
// variant). A cell with volumes is drawn, all of it, by the VOLUMES variant,
// which drops its fragments inside the volumes; each volume's target room is
// then drawn in the same level, shown only inside the volume and tinted.
#include "render/objects/object_draw.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "render/lights/light_draw.hpp"
#include "render/objects/object_culling.hpp"

namespace impossible::render {
namespace {

// A cut as a clip distance in the mesh's coordinates (the plane in the
// cell's through `model`, in double): a strict cut (an image keeps d > 0) is
// moved by kStrictCutShift towards its kept side, so that a face lying in the
// plane (a prop standing against the door) is cut away in the image as the
// tracer cuts it, instead of being kept by the clipper at d = 0. The shift
// covers float32's rounding of the distance the shader computes, from the
// mesh's coordinates (measured from its origin), so it scales with the mesh
// origin's distance from the plane and the mesh's extent, never with the
// cell's distance from the layout's origin: 1 µm times 1254 m opened a 1.25 mm
// gap between a hand's own part and its image at a door 1.25 km out.
inline constexpr double kStrictCutShift = 1e-6;  // metres, times 1 + |d of the mesh origin| + extent
math::dvec4 mesh_cut_plane(const walk::ObjectCut& cut, const math::dmat4& model, double extent) {
    math::dvec4 plane = glm::transpose(model) * cut.plane;
    if (cut.strict) {
        const double unit = glm::length(math::dvec3(plane));  // metres of d per mesh unit (a model's scale)
        plane.w -= kStrictCutShift * (1.0 + std::abs(plane.w) + extent * unit);
    }
    return plane;
}

// The largest coordinate of a mesh's vertices, measured from its origin.
double mesh_extent(const scene::ObjectMesh& mesh) {
    const math::dvec3 far = glm::max(glm::abs(mesh.lo - mesh.origin), glm::abs(mesh.hi - mesh.origin));
    return std::max({far.x, far.y, far.z});
}

// The per-instance uniforms of a variant with kObjectCuts.
void set_instance_uniforms(const SceneProgram& program, const walk::ObjectInstance& inst, const math::dmat4& model,
                           double extent) {
    float planes[2][4];
    for (int k = 0; k < 2; ++k) {
        const math::dvec4 plane = k < inst.cut_count ? mesh_cut_plane(inst.cuts[static_cast<size_t>(k)], model, extent)
                                                     : math::dvec4(0.0, 0.0, 0.0, 1.0);
        for (int c = 0; c < 4; ++c) planes[k][c] = static_cast<float>(plane[c]);
    }
    const glm::mat3 rotation(math::dmat3(inst.to_cell));
    const GLuint p = program.program.get();
    glProgramUniform4fv(p, program.cut_plane, 2, &planes[0][0]);
    glProgramUniformMatrix3fv(p, program.object_rotation, 1, GL_FALSE, &rotation[0][0]);
}

// A batch's material uniforms and texture (portal_draw.cpp's draw_cell does
// the same for a cell's batches).
void set_material(const DrawContext& ctx, const SceneProgram& m, const scene::DrawBatch& b) {
    glProgramUniform1i(m.program.get(), m.mip_level0, ctx.frame.textures_mip_level0 ? 1 : 0);
    glProgramUniform1i(m.program.get(), m.textured, b.texture >= 0 ? 1 : 0);
    glProgramUniform1f(m.program.get(), m.alpha_cutoff, b.alpha_cutoff);
    const GLuint texture = b.texture >= 0 ? ctx.scene.gpu.textures[static_cast<std::size_t>(b.texture)].get() : 0;
    ctx.state.texture(kSceneTextureUnit, texture);
}

bool has_material(const scene::DrawBatch& b) { return b.texture >= 0 || b.alpha_cutoff >= 0.0f; }

void draw_instance(const DrawContext& ctx, const LevelView& view, const Scissor& scissor, int i, int id_cell,
                   int inside) {
    const SceneData& r = ctx.scene;
    const walk::ObjectInstance& inst = ctx.scratch.objects.instances[static_cast<size_t>(i)];
    const scene::ObjectMesh& mesh =
        r.object_meshes[static_cast<size_t>(ctx.scratch.objects.mesh[static_cast<size_t>(i)])];
    const math::dmat4 model = inst.to_cell * glm::translate(math::dmat4(1.0), mesh.origin);
    const double extent = mesh_extent(mesh);
    for (const scene::DrawBatch& b : mesh.batches) {
        const SceneProgram& program =
            cell_program(ctx, view.cell, kObjectCuts | light_flags(ctx) | (has_material(b) ? kMaterials : 0u));
        set_model_uniforms(ctx, view, program, {view.eyes[0].rect, view.eyes[1].rect}, model, glm::vec3(0.0f));
        set_instance_uniforms(program, inst, model, extent);
        set_cell_id(program, static_cast<unsigned>(id_cell + 1), false);
        // Lit in the room it is placed in, from the mesh's coordinates.
        if (r.lighting.lit) {
            const math::dvec3 origin = r.cell_origins[static_cast<size_t>(id_cell)].origin;
            const glm::mat4 to_light(glm::translate(math::dmat4(1.0), -origin) * model);
            set_light_uniforms(ctx.lights, program, id_cell, to_light);
        }
        set_volume_uniforms(ctx, view, program, model, inside);
        if (has_material(b)) set_material(ctx, program, b);
        draw_range(ctx, view, {Pass::Scene, view.level, &program, scissor, kObjectClipDistances}, b.range);
    }
}

// Room `t`'s own batches in a level of another cell (a volume's target, in
// the same coordinates), shown inside volume `inside` only.
void draw_volume_room(const DrawContext& ctx, const LevelView& view, const Scissor& scissor, int t, int inside) {
    const SceneData& r = ctx.scene;
    const scene::CellOrigin& origin = r.cell_origins[static_cast<size_t>(t)];
    const math::dmat4 model = glm::translate(math::dmat4(1.0), origin.origin);
    // Lit by its own room's ambient and lights (layout-format.md, "Lights").
    if (r.lighting.lit) ctx.scratch.stats.light_images += ctx.lights.count[static_cast<size_t>(t)];
    for (const scene::DrawBatch& b : r.cells[static_cast<size_t>(t)]) {
        const SceneProgram& program =
            cell_program(ctx, view.cell, light_flags(ctx) | (has_material(b) ? kMaterials : 0u));
        set_model_uniforms(ctx, view, program, {view.eyes[0].rect, view.eyes[1].rect}, model, origin.checker_offset);
        set_cell_id(program, static_cast<unsigned>(t + 1), false);
        set_room_lights(ctx, program, t, false);
        set_volume_uniforms(ctx, view, program, model, inside);
        if (has_material(b)) set_material(ctx, program, b);
        draw_range(ctx, view, {Pass::Scene, view.level, &program, scissor}, b.range);
    }
}

}  // namespace

const SceneProgram& cell_program(const DrawContext& ctx, int cell, unsigned flags) {
    const SceneData& r = ctx.scene;
    if (!r.volumes[static_cast<size_t>(cell)].empty()) flags |= kVolumes;
    if (flags == 0u) return ctx.scene_program;
    if (flags == kMaterials) {
        assert(ctx.material_program != nullptr);
        return *ctx.material_program;
    }
    const std::optional<SceneProgram>& variant = ctx.programs.variants[static_cast<int>(ctx.frame.stereo)][flags];
    assert(variant);  // prepare_frame built it
    return *variant;
}

void draw_cell_instances(const DrawContext& ctx, const LevelView& view, const Scissor& scissor, int cell, int inside) {
    FrameScratch& s = ctx.scratch;
    if (s.objects.cells.empty()) return;
    const scene::CellObjects& objects = s.objects.cells[static_cast<size_t>(cell)];
    if (objects.objects.empty()) return;
    std::vector<int>& visible = s.visible_instances;
    if (ctx.frame.cull_portals && ctx.frame.cull_objects) {
        // Two pixels of margin, as the cell's own props.
        visible_objects(objects, view, ctx.frame.eye_width, ctx.frame.eye_height, 2.0, s.cull, visible);
    } else {
        visible.resize(objects.objects.size());
        for (size_t k = 0; k < visible.size(); ++k) visible[k] = static_cast<int>(k);
    }
    for (const int k : visible)
        draw_instance(ctx, view, scissor, static_cast<int>(objects.objects[static_cast<size_t>(k)].first_batch), cell,
                      inside);
}

namespace {

// The level's view narrowed, per eye, to where volume `v` may be seen (two
// pixels of margin, as props'): its target room is drawn only there.
LevelView narrowed_to(const DrawContext& ctx, const LevelView& view, const VolumeBox& v) {
    math::dvec3 corners[8];
    for (int k = 0; k < 8; ++k) {
        const double sr = k == 0 || k == 3 || k == 4 || k == 7 ? -1.0 : 1.0;
        const double su = k % 4 < 2 ? -1.0 : 1.0;
        const double sn = k < 4 ? 1.0 : -1.0;
        corners[k] = v.center + sr * v.half.x * v.axes[0] + su * v.half.y * v.axes[1] + sn * v.half.z * v.axes[2];
    }
    LevelView narrowed = view;
    for (EyeView& ev : narrowed.eyes) {
        const NdcRect rect = box_rect(corners, ev);
        ev.rect = rect.empty() ? NdcRect::none()
                               : intersect(widened(rect, 2.0, ctx.frame.eye_width, ctx.frame.eye_height), ev.rect);
    }
    return narrowed;
}

}  // namespace

void draw_volume_rooms(const DrawContext& ctx, const LevelView& view, const Scissor& scissor) {
    const std::vector<VolumeBox>& volumes = ctx.scene.volumes[static_cast<size_t>(view.cell)];
    for (size_t k = 0; k < volumes.size(); ++k) {
        // With culling, the target room is drawn only where the volume may
        // be seen (the rest of it would be discarded fragment by fragment).
        const LevelView narrowed = ctx.frame.cull_portals ? narrowed_to(ctx, view, volumes[k]) : view;
        if (narrowed.eyes[0].rect.empty() && narrowed.eyes[1].rect.empty()) continue;
        const Scissor within = ctx.frame.cull_portals
                                   ? portal_scissor(ctx, narrowed, {narrowed.eyes[0].rect, narrowed.eyes[1].rect})
                                   : scissor;
        draw_volume_room(ctx, narrowed, within, volumes[k].target, static_cast<int>(k));
        draw_cell_instances(ctx, narrowed, within, volumes[k].target, static_cast<int>(k));
    }
}

}  // namespace impossible::render
