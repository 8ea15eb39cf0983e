// A frame's dynamic objects placed once (frame_objects.hpp; layout-format.md,
// "Moving props, hands and crossing objects"): instances, each a mesh, a cell,
// a rigid matrix from the mesh's own coordinates and up to two door planes
// that cut it, with their bounds and a culling tree per cell.
#include "render/objects/frame_objects.hpp"

#include <cassert>
#include <cstdint>
#include <limits>

#include "render/scene_data.hpp"
#include "scene/cell_objects.hpp"

namespace impossible::render {
namespace {

// Where an instance may be seen: its mesh's bounds through its matrix, in
// the cell's coordinates, padded as the cell's own objects are.
scene::CellObject instance_bounds(const scene::ObjectMesh& mesh, const walk::ObjectInstance& inst) {
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    for (int k = 0; k < 8; ++k) {
        const math::dvec3 corner((k & 1) ? mesh.hi.x : mesh.lo.x, (k & 2) ? mesh.hi.y : mesh.lo.y,
                                 (k & 4) ? mesh.hi.z : mesh.lo.z);
        const math::dvec3 p = math::dvec3(inst.to_cell * math::dvec4(corner, 1.0));
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const glm::dvec3 pad = 1e-6 + 1e-9 * glm::max(glm::abs(lo), glm::abs(hi));
    scene::CellObject o;
    o.lo = lo - pad;
    o.hi = hi + pad;
    return o;
}

}  // namespace

void place_frame_objects(const SceneData& r, const FrameDesc& frame, FrameObjects& out, walk::PropWalks* walks) {
    for (const int c : out.touched) {
        scene::CellObjects& cell = out.cells[static_cast<size_t>(c)];
        cell.objects.clear();
        cell.nodes.clear();
        cell.order.clear();
    }
    out.touched.clear();
    out.cells.resize(r.cells.size());
    out.instances = walk::place_objects(r.object_set, frame, walks);
    out.mesh.resize(out.instances.size());
    const int hand_mesh = static_cast<int>(r.object_meshes.size()) - 1;
    for (size_t i = 0; i < out.instances.size(); ++i) {
        const walk::ObjectInstance& inst = out.instances[i];
        const int mesh = inst.kind == walk::ObjectKind::Hand
                             ? hand_mesh
                             : r.prop_mesh[static_cast<size_t>(inst.listed_room)][static_cast<size_t>(inst.index)];
        assert(mesh >= 0);
        out.mesh[i] = mesh;
        scene::CellObjects& cell = out.cells[static_cast<size_t>(inst.cell)];
        if (cell.objects.empty()) out.touched.push_back(inst.cell);
        scene::CellObject o = instance_bounds(r.object_meshes[static_cast<size_t>(mesh)], inst);
        o.first_batch = static_cast<std::uint32_t>(i);
        cell.objects.push_back(o);
    }
    for (const int c : out.touched) scene::build_cull_tree(out.cells[static_cast<size_t>(c)]);
}

}  // namespace impossible::render
