// Dynamic objects' instances in the stencil recursion (object_draw.hpp,
// draw_cell_instances): a level's visible instances of a cell, each with a
// record (its matrix into the cell's coordinates less the cell's origin, and
// its door cuts) in a block indexed by mesh (instance_stream.hpp), which each
// vertex finds by its mesh's slot; their plain batches as runs of the index
// buffer (the meshes of a layout's dynamic props lie one after another), all
// in one multi-draw, the batches with materials one draw each.
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "render/lights/light_draw.hpp"
#include "render/objects/box_faces.hpp"
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

// The faces of box instance `inst` (mesh `mesh`) that an eye of `view` may
// see from the front (box_front_faces, as a cell's still boxes; the eyes
// moved into the mesh's own coordinates); kAllBoxFaces for other meshes.
unsigned instance_box_faces(const LevelView& view, const BoxFaceView& bf, const walk::ObjectInstance& inst,
                            const scene::ObjectMesh& mesh) {
    if (!mesh.box || mesh.batches.size() != 1 || has_material(mesh.batches[0])) return kAllBoxFaces;
    LevelView local = view;
    const math::dmat4 from_cell = glm::inverse(inst.to_cell);
    for (EyeView& ev : local.eyes) {
        ev.eye.position = math::dvec3(from_cell * math::dvec4(ev.eye.position, 1.0));
        ev.view_proj = ev.view_proj * inst.to_cell;
    }
    return box_front_faces(mesh.lo, mesh.hi, local, bf);
}

// Queues the range, joined to the last queued one where it follows it in
// the index buffer (consecutive meshes, as a cell's props are).
void queue_joined(IndirectDraws& draws, const scene::IndexRange& range, int instances) {
    if (range.count == 0) return;
    if (!draws.pending.empty()) {
        IndirectDraw& last = draws.pending.back();
        if (last.first_index + last.count == range.first) {
            last.count += range.count;
            return;
        }
    }
    queue_range(draws, range, instances);
}

// Submits the queued ranges through the instances' vertex array: one
// multi-draw (one draw a range without FrameDesc::multi_draw, and in the
// web build, which has no multi-draw).
void submit_instances(const DrawContext& ctx, const LevelView& view, const SceneDraw& draw) {
    FrameScratch& s = ctx.scratch;
    const GLuint vao = ctx.scene.gpu.instance_vao.get();
#if defined(__EMSCRIPTEN__)
    constexpr bool kMultiDraw = false;
#else
    constexpr bool kMultiDraw = true;
#endif
    if (kMultiDraw && ctx.frame.multi_draw) {
        submit_queued(ctx, view, draw, vao);
        return;
    }
    std::vector<IndirectDraw> commands;
    commands.swap(s.indirect.pending);
    for (const IndirectDraw& d : commands) {
        s.indirect.pending.push_back(d);
        submit_queued(ctx, view, draw, vao);
    }
}

// Writes the records of the instances `order` (by mesh, each mesh once) as
// one block indexed by mesh and binds the texture; returns the record of
// slot 0 (u_record_base).
int write_records(const DrawContext& ctx, const std::vector<int>& order, const math::dvec3& origin) {
    const SceneData& r = ctx.scene;
    FrameScratch& s = ctx.scratch;
    auto mesh_of = [&](int i) { return s.objects.mesh[static_cast<size_t>(i)]; };
    const int low = mesh_of(order.front());
    s.instance_records.pending.assign(static_cast<size_t>(mesh_of(order.back()) - low + 1), InstanceRecord{});
    for (const int i : order) {
        const walk::ObjectInstance& inst = s.objects.instances[static_cast<size_t>(i)];
        const scene::ObjectMesh& mesh = r.object_meshes[static_cast<size_t>(mesh_of(i))];
        const math::dmat4 model = inst.to_cell * glm::translate(math::dmat4(1.0), mesh.origin);
        s.instance_records.pending[static_cast<size_t>(mesh_of(i) - low)] =
            instance_record(inst, model, origin, mesh_extent(mesh));
    }
    const int first = write_instances(s.instance_records, ctx.state);
    ctx.state.texture(kInstanceRecordUnit, s.instance_records.texture.get());
    return first - low;
}

// The instances `order` (indices into the frame's instances, each mesh at
// most once, by mesh) of a level, drawn with id id_cell + 1: their records
// as one block indexed by mesh, their plain batches as runs of the index
// buffer, the batches with materials one draw each.
void draw_instances(const DrawContext& ctx, const LevelView& view, const Scissor& scissor,
                    const std::vector<int>& order, int id_cell, int inside) {
    const SceneData& r = ctx.scene;
    FrameScratch& s = ctx.scratch;
    const math::dvec3 origin = r.cell_origins[static_cast<size_t>(view.cell)].origin;
    auto mesh_of = [&](int i) { return s.objects.mesh[static_cast<size_t>(i)]; };
    const int base = write_records(ctx, order, origin);
    const int eyes = instances_of(ctx);
    const unsigned flags = kObjectCuts | light_flags(ctx, id_cell, &view);
    const SceneProgram& plain = cell_program(ctx, view, flags);
    set_instanced_uniforms(ctx, view, plain, id_cell, inside);
    glProgramUniform1i(plain.program.get(), plain.record_base, base);
    assert(s.indirect.pending.empty());
    // The cuts' clip distances only where some instance has a cut.
    bool cut = false;
    for (const int i : order) cut = cut || s.objects.instances[static_cast<size_t>(i)].cut_count > 0;
    const int clip_distances = cut ? kObjectClipDistances : kSceneClipDistances;
    // Box props' faces an eye may see, as still boxes' (FrameDesc::cull_box_faces),
    // through the face stream; other meshes' plain batches as runs.
    const bool box_faces = ctx.frame.cull_portals && ctx.frame.cull_objects && ctx.frame.cull_box_faces;
    const BoxFaceView bf = box_face_view(view, ctx.frame.eye_width, ctx.frame.eye_height, ctx.frame.samples);
    assert(s.faces.pending.empty());
    bool any_material = false;
    for (const int i : order) {
        const scene::ObjectMesh& mesh = r.object_meshes[static_cast<size_t>(mesh_of(i))];
        const unsigned faces =
            box_faces ? instance_box_faces(view, bf, s.objects.instances[static_cast<size_t>(i)], mesh) : kAllBoxFaces;
        if (faces != kAllBoxFaces) {
            append_box_faces(mesh.first_vertex, faces, s.faces.pending);
            continue;
        }
        for (const scene::DrawBatch& b : mesh.batches) {
            any_material = any_material || has_material(b);
            if (!has_material(b)) queue_joined(s.indirect, b.range, eyes);
        }
    }
    const SceneDraw plain_draw{Pass::Scene, view.level, &plain, scissor, clip_distances};
    submit_instances(ctx, view, plain_draw);
    if (!s.faces.pending.empty()) {
        const auto count = static_cast<std::uint32_t>(s.faces.pending.size());
        queue_range(s.indirect, {upload_faces(s.faces, r.gpu.face_indices.get()), count}, eyes);
        submit_queued(ctx, view, plain_draw, r.gpu.instance_face_vao.get());
    }
    if (!any_material) return;
    const SceneProgram& with_material = cell_program(ctx, view, flags | kMaterials);
    set_instanced_uniforms(ctx, view, with_material, id_cell, inside);
    glProgramUniform1i(with_material.program.get(), with_material.record_base, base);
    for (const int i : order)
        for (const scene::DrawBatch& b : r.object_meshes[static_cast<size_t>(mesh_of(i))].batches) {
            if (!has_material(b) || b.range.count == 0) continue;
            set_material(ctx, with_material, b);
            queue_range(s.indirect, b.range, eyes);
            submit_instances(ctx, view, {Pass::Scene, view.level, &with_material, scissor, clip_distances});
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
    // By mesh; a mesh seen twice in the cell (an object and its image
    // through a door into its own room) goes into a second layer, its own
    // block of records and draws.
    std::vector<std::pair<int, int>>& by_mesh = s.instance_order;
    by_mesh.clear();
    for (const int k : visible) {
        const int i = static_cast<int>(objects.objects[static_cast<size_t>(k)].first_batch);
        by_mesh.emplace_back(s.objects.mesh[static_cast<size_t>(i)], i);
    }
    std::sort(by_mesh.begin(), by_mesh.end());
    std::vector<int>& layer = s.visible_instances;  // visible is read no further
    for (bool more = true; more;) {
        more = false;
        layer.clear();
        for (std::pair<int, int>& m : by_mesh) {
            if (m.second < 0) continue;
            if (!layer.empty() && s.objects.mesh[static_cast<size_t>(layer.back())] == m.first) {
                more = true;
                continue;
            }
            layer.push_back(m.second);
            m.second = -1;
        }
        if (!layer.empty()) draw_instances(ctx, view, scissor, layer, cell, inside);
    }
}

}  // namespace impossible::render
