// Internal to src/render: what a Renderer keeps between frames, shared by the
// files that draw a frame (renderer.cpp, portal_*.cpp).
#pragma once

#include <optional>
#include <vector>

#include "gl/handles.hpp"
#include "gl/state.hpp"
#include "math/portal.hpp"
#include "render/gpu_scene.hpp"
#include "render/multi_draw.hpp"
#include "render/multisample.hpp"
#include "render/object_culling.hpp"
#include "render/scene_program.hpp"
#include "render/target.hpp"
#include "links/portal_links.hpp"
#include "scene/scene.hpp"

namespace impossible::render {

inline constexpr int kStereoModeCount = 3;

// A window's reflected view, copied aside while the view through it is drawn
// (portal_glass.cpp): a texture like the target's colour, one per window
// nesting level in use.
struct SavedColour {
    gl::Texture texture;
    int width = 0, height = 0, samples = 1;
};

struct RendererData {
    gl::StateCache* state = nullptr;  // the context's; outlives the renderer
    std::vector<std::vector<scene::DrawBatch>> cells;  // per room: its batches, into gpu's index buffer
    std::vector<scene::CellObjects> objects;  // per room: the same split for per-object culling
    CullScratch cull_scratch;                 // reused by every level (object_culling.hpp)
    std::vector<scene::DrawBatch> cull_batches;
    IndirectDraws indirect;                   // FrameDesc::multi_draw's commands, rewritten every frame
    std::vector<scene::CellFrame> frames;  // per room: what its vertices are relative to
    std::vector<scene::PortalInfo> portals;  // per portal, as the scene has it
    std::vector<scene::PortalMesh> portal_meshes;  // per portal: its box (a mirror's or window's: the front alone)
    bool has_windows = false;              // the window blend's programs are needed
    links::PortalLinks links;              // M_AB per portal, the portals of each room
    GpuScene gpu;
    std::optional<SceneProgram> programs[kStereoModeCount];  // per StereoMode, built on first use
    std::optional<SceneProgram> material_programs[kStereoModeCount];  // the same with textures and cut-outs
    bool has_materials = false;  // some batch has a texture or an alpha cutoff
    ClearDepthProgram clear_depth;
    gl::VertexArray empty_vao;            // for the attribute-less clear triangle
    Target target;                        // single-sample: what is read back or shown
    Multisampling multisampling;          // with FrameDesc::samples > 1
    std::vector<gl::Query> mark_queries;  // occlusion queries of portal marks, reused every frame
    std::optional<SceneProgram> portal_texture_program;  // render-to-texture portals, built on first use
    std::vector<Target> portal_textures;  // one per portal of the head's cell, reused every frame
    std::optional<WindowBlendProgram> window_blend[2];  // single-sample, multisample copies; built on first use
    std::vector<SavedColour> saved_colours;  // per window nesting level, made on first use
};

// Clears a target to the background colour, id 0, far depth (for its depth
// mode) and the given stencil value, through the state cache.
void clear_target(RendererData& r, const Target& target, int stencil);

// For FrameDesc::samples > 1 (multisample.cpp): checks the count, makes the
// multisampled target of the frame's size and the framebuffers the resolve
// writes through; nothing for 1 sample. Call after `target` is made.
Result<void> ensure_multisampled(RendererData& r, const FrameDesc& frame);

// The target the frame's passes draw into: `target`, or the multisampled one.
Target& drawing_target(RendererData& r, const FrameDesc& frame);

// Resolves the frame's multisampled target into `target` (colour averaged,
// ids by majority); nothing for 1 sample.
void resolve_multisampled(RendererData& r, const FrameDesc& frame);

}  // namespace impossible::render
