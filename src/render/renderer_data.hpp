// Internal to src/render: what a Renderer keeps, by how long it lives.
//
// - RendererData is fixed for the renderer's life: the scene's tables, the
//   GPU scene and the programs (a stereo mode's, or a feature's, built before
//   the first frame that needs it and never changed after). Drawing a frame
//   only reads it.
// - FrameTargets are what frames are drawn into, remade before a frame that
//   asks for another size, depth mode or sample count.
// - FrameScratch is the scratch of one frame: pools reused from frame to
//   frame, how much of them the frame has used, and its counters; reset by
//   begin_frame().
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "gl/handles.hpp"
#include "gl/state.hpp"
#include "links/portal_links.hpp"
#include "render/frame.hpp"
#include "render/lights/light_buffers.hpp"
#include "render/lights/shadow_maps.hpp"
#include "render/objects/box_faces.hpp"
#include "render/objects/frame_objects.hpp"
#include "render/objects/multi_draw.hpp"
#include "render/objects/object_culling.hpp"
#include "render/programs/gpu_scene.hpp"
#include "render/programs/scene_program.hpp"
#include "render/target.hpp"
#include "render/targets/hidden_mask.hpp"
#include "render/targets/multisample.hpp"
#include "scene/scene.hpp"
#include "walk/objects.hpp"
#include "walk/prop_walks.hpp"

namespace impossible::render {

inline constexpr int kStereoModeCount = 3;

// Every program a renderer draws with.
struct Programs {
    std::optional<SceneProgram> scene[kStereoModeCount];     // per StereoMode
    std::optional<SceneProgram> material[kStereoModeCount];  // the same with textures and cut-outs
    std::optional<SceneProgram> portal_texture;              // render-to-texture portals
    // The variants with kObjectCuts or kVolumes (scene_program.hpp), per
    // StereoMode and flags, built before the first frame that needs them.
    std::optional<SceneProgram> variants[kStereoModeCount][kSceneVariantCount];
    std::optional<SceneProgram> portal_texture_volumes;  // render-to-texture portals of a cell with volumes
    std::optional<WindowBlendProgram> window_blend[2];   // single-sample, multisample copies
    std::vector<gl::Program> id_resolve;                 // the multisample id resolve per sample count (index: count)
    ClearDepthProgram clear_depth;                       // built with the renderer
};

// A volume portal (layout-format.md, "Volume portals") as the renderer draws
// it: its box in layout coordinates and the room shown inside it.
struct VolumeBox {
    math::dvec3 center{0.0};
    std::array<math::dvec3, 3> axes{};  // r, u, n: unit
    math::dvec3 half{0.0};              // half the width, height, depth
    int target = -1;                    // the room shown inside
    glm::dvec3 tint{1.0};
};

struct RendererData {
    gl::StateCache* state = nullptr;                   // the context's; outlives the renderer
    std::vector<std::vector<scene::DrawBatch>> cells;  // per room: its batches, into gpu's index buffer
    std::vector<scene::CellObjects> objects;           // per room: the same split for per-object culling
    std::vector<scene::CellOrigin> cell_origins;       // per room: the origin its vertices are relative to
    std::vector<scene::PortalInfo> portals;            // per portal, as the scene has it
    std::vector<scene::PortalMesh> portal_meshes;      // per portal: its box (a mirror's or window's: the front)
    links::PortalLinks links;                          // M_AB per portal, the portals of each room
    bool has_windows = false;                          // the window blend's programs are needed
    bool has_materials = false;                        // some batch has a texture or an alpha cutoff
    walk::ObjectSet object_set;                        // the dynamic props and the hand (scene.hpp)
    std::vector<scene::ObjectMesh> object_meshes;      // per object_set.props, then the hand
    std::vector<std::vector<int>> prop_mesh;           // per room, per prop: its object mesh, or -1 (static)
    bool object_materials = false;                     // some object mesh batch has a texture or a cutoff
    std::vector<std::vector<VolumeBox>> volumes;       // per room: its volume portals
    bool has_volumes = false;                          // some room has a volume
    // Every room's volumes, 4 vec4s each (the VOLUMES shaders' inside test,
    // relative to the room's cell origin), at kVolumeBinding while drawing;
    // volume_first[room] is the room's first.
    gl::Buffer volume_boxes;
    std::vector<int> volume_first;
    // Under "lighting": "lights": the scene's images at its light depth, the
    // layout (for another depth, View::light_depth), and the images of the
    // depth last drawn on the GPU (made before the frame that needs them).
    bool lit = false;
    int scene_light_depth = 0;
    int max_light_depth = layout::kMaxLightDepth;  // Scene::max_light_depth
    std::vector<lights::RoomLights> scene_room_lights;
    std::shared_ptr<const layout::Layout> lit_layout;
    LightBuffers lights;
    ShadowMaps shadow_maps;  // the props' shadows of `lights` (render/shadow_maps.hpp)
    GpuScene gpu;
    gl::VertexArray empty_vao;  // for the attribute-less full-target triangle
    Programs programs;
};

struct FrameTargets {
    Target target;                        // single-sample: what is read back or shown
    Multisampling multisampling;          // with FrameDesc::samples > 1
    std::vector<Target> portal_textures;  // one per portal of the head's cell (render-to-texture portals)
    HiddenMask hidden_mask;               // the frame's hidden areas (headset optics)
};

// A window's reflected view, copied aside while the view through it is drawn
// (portal_glass.cpp): a texture like the target's colour, one per window
// being drawn (a window's views may show windows, drawn inside its own).
struct SavedColour {
    gl::Texture texture;
    int width = 0, height = 0, samples = 1;
};

struct FrameScratch {
    FrameStats stats;
    CullScratch cull;  // reused by every level (object_culling.hpp)
    std::vector<scene::DrawBatch> cull_batches;
    FrameObjects objects;  // the frame's dynamic objects (object_draw.cpp)
    // The moving props walked from frame to frame (only the keys passed
    // since the last frame), over RendererData::object_set.
    std::unique_ptr<walk::PropWalks> prop_walks;
    std::vector<int> visible_instances;
    IndirectDraws indirect;                  // FrameDesc::multi_draw's commands
    FaceStream faces;                        // FrameDesc::cull_box_faces's indices (box_faces.hpp)
    std::vector<VisibleDraw> cull_draws;     // a level's draws with box faces culled
    std::vector<gl::Query> mark_queries;     // occlusion queries of portals, made on first use
    size_t mark_queries_used = 0;            // of mark_queries, by this frame
    std::vector<SavedColour> saved_colours;  // per window being drawn, made on first use
    size_t saved_colours_used = 0;           // of saved_colours, by the windows being drawn
    bool conditional = false;                // inside a portal's conditional rendering

    // Empty counters and nothing of the pools used.
    void begin_frame() {
        stats = {};
        begin_indirect_frame(indirect);
        faces.used = 0;
        mark_queries_used = 0;
        saved_colours_used = 0;
        conditional = false;
    }
};

// All a Renderer owns.
struct RendererParts {
    RendererData data;
    FrameTargets targets;
    FrameScratch scratch;
};

// Clears a target to the background colour, id 0, far depth (for its depth
// mode) and the given stencil value, through the state cache.
void clear_target(gl::StateCache& state, const Target& target, int stencil);

// For FrameDesc::samples > 1 (multisample.cpp): checks the count, makes the
// multisampled target of the frame's size, the framebuffers the resolve
// writes through and the id resolve's program; nothing for 1 sample. Call
// after `targets.target` is made.
Result<void> ensure_multisampled(Programs& programs, FrameTargets& targets, const FrameDesc& frame);

// The target the frame's passes draw into: `target`, or the multisampled one.
const Target& drawing_target(const FrameTargets& targets, const FrameDesc& frame);

// Resolves the frame's multisampled target into `target` (colour averaged,
// ids by majority); nothing for 1 sample.
void resolve_multisampled(const RendererData& r, const FrameTargets& targets, const FrameDesc& frame);

}  // namespace impossible::render
