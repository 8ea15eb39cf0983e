// Dynamic objects' instances in the stencil recursion (object_draw.hpp,
// draw_cell_instances): a level's visible instances of a cell, each with a
// per-instance record (its matrix into the cell's coordinates less the
// cell's origin, and its door cuts; instance_stream.hpp), all their plain
// batches in one multi-draw whose commands name their records as base
// instances, the batches with materials one draw each. In the web build
// (no base instance in WebGL 2) each command is its own draw, its records
// bound at their offset.
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "render/lights/light_draw.hpp"
#include "render/objects/instance_stream.hpp"
#include "render/objects/object_culling.hpp"
#include "render/objects/object_draw.hpp"

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

// An instance's record (instance_stream.hpp): `model` (mesh → layout) less
// the origin `cell_origin` of the level's cell, and its cuts, in double
// until the last rounding to float.
InstanceRecord instance_record(const walk::ObjectInstance& inst, const math::dmat4& model,
                               const math::dvec3& cell_origin, double extent) {
    InstanceRecord record;
    const math::dmat4 relative = glm::translate(math::dmat4(1.0), -cell_origin) * model;
    for (int row = 0; row < 3; ++row)
        for (int c = 0; c < 4; ++c) record.model_rows[row][c] = static_cast<float>(relative[c][row]);
    for (int k = 0; k < 2; ++k) {
        const math::dvec4 plane = k < inst.cut_count ? mesh_cut_plane(inst.cuts[static_cast<size_t>(k)], model, extent)
                                                     : math::dvec4(0.0, 0.0, 0.0, 1.0);
        for (int c = 0; c < 4; ++c) record.cut_planes[k][c] = static_cast<float>(plane[c]);
    }
    return record;
}

// The uniforms an instanced draw of a level shares: the cell's eyes, the
// checker pattern in the mesh's own coordinates, the id, the lights of room
// `id_cell` and the volumes.
void set_instanced_uniforms(const DrawContext& ctx, const LevelView& view, const SceneProgram& program, int id_cell,
                            int inside) {
    const SceneData& r = ctx.scene;
    const math::dvec3 origin = r.cell_origins[static_cast<size_t>(view.cell)].origin;
    set_eye_uniforms(ctx, view, program, {view.eyes[0].rect, view.eyes[1].rect});
    const glm::vec3 no_offset(0.0f);
    glProgramUniform3fv(program.program.get(), program.checker_offset, 1, &no_offset[0]);
    set_cell_id(program, static_cast<unsigned>(id_cell + 1), false);
    // Lit in the room it is placed in: the level cell's coordinates less
    // that room's origin.
    if (r.lighting.lit) {
        const math::dvec3 lit_origin = r.cell_origins[static_cast<size_t>(id_cell)].origin;
        set_light_uniforms(ctx.lights, program, id_cell,
                           glm::mat4(glm::translate(math::dmat4(1.0), origin - lit_origin)));
    }
    set_volume_uniforms(ctx, view, program, glm::translate(math::dmat4(1.0), origin), inside);
}

// Submits the queued commands through the instances' vertex array, whose
// records start at byte `records`: one multi-draw (or, without
// FrameDesc::multi_draw, and in the web build, one draw a command).
void submit_instances(const DrawContext& ctx, const LevelView& view, const SceneDraw& draw, std::size_t records) {
    FrameScratch& s = ctx.scratch;
    const GLuint vao = ctx.scene.gpu.instance_vao.get();
    const GLuint buffer = s.instance_records.buffer.get();
#if defined(__EMSCRIPTEN__)
    constexpr bool kBaseInstance = false;
#else
    constexpr bool kBaseInstance = true;
#endif
    if (kBaseInstance && ctx.frame.multi_draw) {
        glVertexArrayVertexBuffer(vao, kInstanceBinding, buffer, static_cast<GLintptr>(records),
                                  sizeof(InstanceRecord));
        submit_queued(ctx, view, draw, vao);
        return;
    }
    std::vector<IndirectDraw> commands;
    commands.swap(s.indirect.pending);
    for (IndirectDraw d : commands) {
        const std::size_t at = records + d.base_instance * sizeof(InstanceRecord);
        glVertexArrayVertexBuffer(vao, kInstanceBinding, buffer, static_cast<GLintptr>(at), sizeof(InstanceRecord));
        d.base_instance = 0;
        s.indirect.pending.push_back(d);
        submit_queued(ctx, view, draw, vao);
    }
}

// The visible instances `order` (indices into the frame's instances) of a
// level, drawn with id id_cell + 1.
void draw_instances(const DrawContext& ctx, const LevelView& view, const Scissor& scissor,
                    const std::vector<int>& order, int id_cell, int inside) {
    const SceneData& r = ctx.scene;
    FrameScratch& s = ctx.scratch;
    const math::dvec3 origin = r.cell_origins[static_cast<size_t>(view.cell)].origin;
    bool any_material = false;
    for (const int i : order) {
        const walk::ObjectInstance& inst = s.objects.instances[static_cast<size_t>(i)];
        const scene::ObjectMesh& mesh = r.object_meshes[static_cast<size_t>(s.objects.mesh[static_cast<size_t>(i)])];
        const math::dmat4 model = inst.to_cell * glm::translate(math::dmat4(1.0), mesh.origin);
        s.instance_records.pending.push_back(instance_record(inst, model, origin, mesh_extent(mesh)));
    }
    const std::size_t records = write_instances(s.instance_records);
    glVertexArrayBindingDivisor(r.gpu.instance_vao.get(), kInstanceBinding, static_cast<GLuint>(instances_of(ctx)));
    const int eyes = instances_of(ctx);
    const unsigned flags = kObjectCuts | light_flags(ctx);
    // Every plain batch of every instance in one submission.
    const SceneProgram& plain = cell_program(ctx, view, flags);
    set_instanced_uniforms(ctx, view, plain, id_cell, inside);
    assert(s.indirect.pending.empty());
    for (size_t j = 0; j < order.size(); ++j)
        for (const scene::DrawBatch& b :
             r.object_meshes[static_cast<size_t>(s.objects.mesh[static_cast<size_t>(order[j])])].batches) {
            if (has_material(b)) {
                any_material = true;
                continue;
            }
            if (b.range.count > 0)
                s.indirect.pending.push_back(
                    {b.range.count, static_cast<std::uint32_t>(eyes), b.range.first, 0, static_cast<std::uint32_t>(j)});
        }
    submit_instances(ctx, view, {Pass::Scene, view.level, &plain, scissor, kObjectClipDistances}, records);
    if (!any_material) return;
    const SceneProgram& with_material = cell_program(ctx, view, flags | kMaterials);
    set_instanced_uniforms(ctx, view, with_material, id_cell, inside);
    for (size_t j = 0; j < order.size(); ++j)
        for (const scene::DrawBatch& b :
             r.object_meshes[static_cast<size_t>(s.objects.mesh[static_cast<size_t>(order[j])])].batches) {
            if (!has_material(b) || b.range.count == 0) continue;
            set_material(ctx, with_material, b);
            s.indirect.pending.push_back(
                {b.range.count, static_cast<std::uint32_t>(eyes), b.range.first, 0, static_cast<std::uint32_t>(j)});
            submit_instances(ctx, view, {Pass::Scene, view.level, &with_material, scissor, kObjectClipDistances},
                             records);
        }
}

}  // namespace

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
    if (visible.empty()) return;
    std::vector<int>& order = s.instance_order;
    order.clear();
    for (const int k : visible) order.push_back(static_cast<int>(objects.objects[static_cast<size_t>(k)].first_batch));
    draw_instances(ctx, view, scissor, order, cell, inside);
}

}  // namespace impossible::render
