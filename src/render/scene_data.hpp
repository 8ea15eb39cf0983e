// Internal to src/render: what a renderer keeps of its scene, fixed for the
// layout. Renderer::create copies it from the scene::Scene (and uploads the
// scene's vertex arrays, not kept on the CPU); drawing a frame only reads it.
// What frames change is elsewhere (renderer_parts.hpp).
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "gl/handles.hpp"
#include "layout/layout.hpp"
#include "lights/light_images.hpp"
#include "links/portal_links.hpp"
#include "math/conventions.hpp"
#include "render/programs/gpu_scene.hpp"
#include "scene/scene.hpp"
#include "walk/objects.hpp"

namespace impossible::render {

// A volume portal (layout-format.md, "Volume portals") as the renderer draws
// it: its box in layout coordinates and the room shown inside it.
struct VolumeBox {
    math::dvec3 center{0.0};
    std::array<math::dvec3, 3> axes{};  // r, u, n: unit
    math::dvec3 half{0.0};              // half the width, height, depth
    int target = -1;                    // the room shown inside
    // The target's triangles that may lie inside, in pieces with their
    // bounds (scene::Scene::volume_pieces): drawn with culling.
    std::vector<scene::VolumePiece> target_pieces;
    glm::dvec3 tint{1.0};
};

// Under "lighting": "lights" (layout-format.md, "Lights"): what the scene
// gives to make the light images of any light depth (lights/light_state.hpp
// makes them on the GPU, for the depth a frame asks).
struct SceneLights {
    bool lit = false;
    int scene_light_depth = 0;                     // the depth of scene_room_lights
    int max_light_depth = layout::kMaxLightDepth;  // Scene::max_light_depth
    std::vector<lights::RoomLights> scene_room_lights;
    // The layout itself, shared and never changed: the only part of the
    // layout a renderer keeps (renderer.hpp's "reads nothing of the layout"
    // holds for "fixed" layouts). The light images of another depth are
    // traced from it (lights::light_images), and every upload reads the
    // lights' colours, intensities, ranges and cones from it.
    std::shared_ptr<const layout::Layout> lit_layout;
    // The scene's geometry, kept on the CPU for the light cache
    // (render/lights/light_cache.hpp).
    std::vector<scene::Vertex> vertices;
    std::vector<std::uint32_t> indices;
};

struct SceneData {
    std::vector<std::vector<scene::DrawBatch>> cells;  // per room: its batches, into gpu's index buffer
    std::vector<scene::CellObjects> objects;           // per room: the same split for per-object culling
    std::vector<scene::CellOrigin> cell_origins;       // per room: the origin its vertices are relative to
    std::vector<scene::PortalInfo> portals;            // per portal, as the scene has it
    std::vector<scene::PortalMesh> portal_meshes;      // per portal: its box (a mirror's or window's: the front)
    links::PortalLinks links;                          // M_AB per portal, the portals of each room
    bool has_windows = false;                          // the window blend's programs are needed
    bool has_materials = false;                        // some batch has a texture or an alpha cutoff
    double exposure = 0.0;                             // the layout's "exposure" (scene::Scene::exposure)
    walk::ObjectSet object_set;                        // the dynamic props and the hand (scene.hpp)
    std::vector<scene::ObjectMesh> object_meshes;      // per object_set.props, then the hand
    std::vector<std::vector<int>> prop_mesh;           // per room, per prop: its object mesh, or -1 (static)
    std::vector<std::vector<VolumeBox>> volumes;       // per room: its volume portals
    bool has_volumes = false;                          // some room has a volume
    // Every room's volumes, 4 vec4s each (the VOLUMES shaders' inside test,
    // relative to the room's cell origin), at kVolumeBinding while drawing;
    // volume_first[room] is the room's first.
    gl::Buffer volume_boxes;
    std::vector<int> volume_first;
    SceneLights lighting;
    GpuScene gpu;
};

// Copies the scene's tables into `out` and uploads its geometry and
// textures (GpuScene) and its volumes' buffer. Needs a current context.
void copy_scene(SceneData& out, const scene::Scene& scene);

}  // namespace impossible::render
