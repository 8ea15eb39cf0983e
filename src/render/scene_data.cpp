// The scene's tables as a renderer keeps them (scene_data.hpp).
#include "render/scene_data.hpp"

#include <cstddef>

#include "math/portal.hpp"

namespace impossible::render {
namespace {

void copy_volumes(SceneData& r, const scene::Scene& scene);

// The scene's dynamic objects and volumes, as the renderer draws them.
void copy_objects(SceneData& r, const scene::Scene& scene) {
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
void copy_volumes(SceneData& r, const scene::Scene& scene) {
    r.volumes.assign(scene.cells.size(), {});
    r.volume_first.assign(scene.cells.size(), 0);
    std::vector<float> boxes;
    for (size_t c = 0; c < scene.volumes.size(); ++c) {
        r.volume_first[c] = static_cast<int>(boxes.size() / 16);
        for (size_t k = 0; k < scene.volumes[c].size(); ++k) {
            const layout::Volume& v = scene.volumes[c][k];
            VolumeBox box;
            box.center = v.rect.center;
            box.axes = {math::portal_right(v.rect), v.rect.up, v.rect.normal};
            box.half = 0.5 * math::dvec3(v.rect.width, v.rect.height, v.rect.depth);
            box.target = v.target_room;
            box.tint = v.tint;
            box.target_pieces = scene.volume_pieces[c][k];
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

void copy_scene(SceneData& r, const scene::Scene& scene) {
    r.cells = scene.batches;
    r.objects = scene.objects;
    for (const auto& cell : scene.batches)
        for (const scene::DrawBatch& b : cell)
            r.has_materials = r.has_materials || b.texture >= 0 || b.alpha_cutoff >= 0.0f;
    copy_objects(r, scene);
    r.cell_origins = scene.origins;
    r.exposure = scene.exposure;
    SceneLights& lighting = r.lighting;
    lighting.lit = scene.lighting == layout::Lighting::Lights && scene.lit_layout != nullptr;
    if (lighting.lit) {
        lighting.scene_light_depth = scene.light_depth;
        lighting.max_light_depth = scene.max_light_depth;
        lighting.scene_room_lights = scene.room_lights;
        lighting.lit_layout = scene.lit_layout;
        lighting.vertices = scene.vertices;
        lighting.indices = scene.indices;
    }
    r.links = scene.links;
    r.portals = scene.portal_info;
    r.portal_meshes = scene.portals;
    for (const scene::PortalInfo& p : scene.portal_info)
        r.has_windows = r.has_windows || p.kind == layout::PortalKind::Window;
    r.gpu = upload_scene(scene);
}

}  // namespace impossible::render
