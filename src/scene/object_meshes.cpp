#include "scene/object_meshes.hpp"

#include <type_traits>
#include <variant>

#include "scene/box_mesh.hpp"
#include "scene/cell_objects.hpp"

namespace impossible::scene {
namespace {

// One object's triangles from `origin`, its batches and its bounds.
template <class AppendFn>
ObjectMesh object_mesh(Scene& scene, MeshWriter& out, const glm::dvec3& origin, AppendFn&& append) {
    ObjectMesh mesh;
    mesh.origin = origin;
    out.origin = origin;
    const auto first_vertex = static_cast<std::uint32_t>(scene.vertices.size());
    append(mesh.batches);
    CellObject bounds;
    bound_object(scene, first_vertex, origin, bounds);
    mesh.lo = bounds.lo;
    mesh.hi = bounds.hi;
    mesh.first_vertex = first_vertex;
    mesh.vertex_end = static_cast<std::uint32_t>(scene.vertices.size());
    return mesh;
}

void append_prop_to(MeshWriter& out, const layout::Prop& prop, std::vector<DrawBatch>& batches) {
    std::visit(
        [&](const auto& p) {
            if constexpr (std::is_same_v<std::decay_t<decltype(p)>, layout::BoxProp>) {
                const std::uint32_t first = out.index_count();
                append_box_prop(out, p);
                add_batch(batches, DrawBatch{out.range_since(first)});
            } else {
                append_gltf_prop(out, p, batches);
            }
        },
        prop);
}

}  // namespace

void append_object_meshes(Scene& scene, MeshWriter& out, const layout::Layout& layout) {
    const walk::ObjectSet& set = scene.object_set;
    scene.object_meshes.reserve(set.props.size() + 1);
    for (const walk::DynamicProp& d : set.props) {
        const layout::Prop& prop =
            layout.rooms[static_cast<std::size_t>(d.room)].props[static_cast<std::size_t>(d.index)];
        const glm::dvec3 origin = scene.origins[static_cast<std::size_t>(d.room)].origin;
        scene.object_meshes.push_back(
            object_mesh(scene, out, origin, [&](std::vector<DrawBatch>& b) { append_prop_to(out, prop, b); }));
        scene.object_meshes.back().box = std::holds_alternative<layout::BoxProp>(prop);
    }
    const layout::HandShape& hand = layout.hands;
    scene.object_meshes.push_back(object_mesh(scene, out, glm::dvec3(0.0), [&](std::vector<DrawBatch>& b) {
        if (hand.model) {
            layout::GltfProp model = *hand.model;
            model.position = glm::dvec3(0.0);
            model.yaw_deg = 0.0;
            append_gltf_prop(out, model, b);
            return;
        }
        layout::BoxProp box;
        box.min = -0.5 * hand.box;
        box.max = 0.5 * hand.box;
        box.color = hand.color;
        append_prop_to(out, box, b);
    }));
    scene.object_meshes.back().box = !hand.model;
}

}  // namespace impossible::scene
