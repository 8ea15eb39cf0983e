// Internal to src/render: the context a frame's draws share, and the draws
// themselves, each of which names all the state it depends on.
//
// As in bgfx's stencil example (examples/13-stencil, s_renderStates[...]
// passed with every submit), a draw names its pass (the PassState of the
// table in passes.hpp), its stencil reference, its program and its scissor;
// the rest follows from the frame (the target, the stereo mode's viewports,
// the clip control) and from the kind of draw (the scene's vertex array, or
// none for a full-target triangle). Everything is applied through the state
// cache (gl/state.hpp) right before the GL call: what GL holds already costs
// nothing, so no draw puts anything back after itself.
#pragma once

#include <array>
#include <optional>

#include <glm/vec3.hpp>

#include "gl/state.hpp"
#include "render/draw/frame_profiler.hpp"
#include "render/draw/frame_scratch.hpp"
#include "render/lights/light_buffers.hpp"
#include "render/portals/passes.hpp"
#include "render/portals/view.hpp"
#include "render/programs/programs.hpp"
#include "render/scene_data.hpp"
#include "render/targets/frame_targets.hpp"

namespace impossible::render {

// One frame as its draws see it (a render-to-texture portal's view is a frame
// of its own, into its texture, sharing the scratch). Everything but
// `scratch` is fixed while the frame is drawn.
struct DrawContext {
    gl::StateCache& state;       // the context's
    const SceneData& scene;      // fixed for the layout
    const Programs& programs;    // every program the frame may draw with (built by prepare_frame)
    const LightBuffers& lights;  // a lit layout's light images of the frame's light depth
    const FrameDesc& frame;
    const SceneProgram& scene_program;     // the frame's stereo mode's
    const SceneProgram* material_program;  // the same with materials; null when no batch has them
    const Target& target;                  // what is drawn into
    const FrameTargets& targets;           // the portal textures
    // Each eye's projection (the same unless the frame gives per-eye frusta).
    std::array<math::dmat4, 2> projections{math::dmat4{1.0}, math::dmat4{1.0}};
    int eye = -1;                       // two-pass stereo: the eye being drawn; -1: both
    FrameProfiler* profiler = nullptr;  // null unless FrameDesc::profile
    FrameScratch& scratch;              // the only thing drawing writes, besides GL
};

// Where a draw may write: a rectangle of the target, or all of it.
using Scissor = std::optional<gl::ScissorRect>;

// How a door box's faces are drawn against a room's or prop's face in the
// same place (layout-format.md, "What a pixel shows", coplanar surfaces;
// docs/choices.md): a front face loses (its depth is moved away from the
// eye by a polygon offset), an inner face seen by an eye behind the plane
// wins (moved towards it).
enum class CoplanarTie { None, Loses, Wins };

// A draw of the scene's geometry (a cell's batches, a portal's box) for the
// eyes of a level, through the scene's vertex array and the stereo mode's
// viewports.
struct SceneDraw {
    Pass pass = Pass::Scene;
    int stencil_ref = 0;  // the recursion level (or the next, passes.hpp)
    const SceneProgram* program = nullptr;
    Scissor scissor;
    // GL_CLIP_DISTANCE0 .. n - 1 enabled: the pass's (kSceneClipDistances),
    // or kObjectClipDistances for an object's instance (its door cuts).
    int clip_distances = kSceneClipDistances;
    CoplanarTie tie = CoplanarTie::None;  // a door box's faces (draw_portal_box)
};

// A full-target triangle (or the eyes' quads of a depth reset) through a
// program of shaders/clear_depth.vert.glsl, which has no eye: drawn through
// the whole target (viewport 0 widened to it with per-eye viewports; the
// eye's viewport in two-pass stereo).
struct TargetDraw {
    Pass pass = Pass::ClearDepth;
    int stencil_ref = 0;
    GLuint program = 0;
    Scissor scissor;
    glm::vec3 blend_color{1.0f};  // K of the passes that blend with it (gl::Blend)
};

// Binds everything the draw names or implies, through the cache.
void bind_draw(const DrawContext& ctx, const LevelView& view, const SceneDraw& draw);
void bind_draw(const DrawContext& ctx, const LevelView& view, const TargetDraw& draw);

// One instanced draw (one per eye in two-pass stereo) of an index range.
void draw_range(const DrawContext& ctx, const LevelView& view, const SceneDraw& draw, const scene::IndexRange& range);

// Submits the ranges queued in the scratch's IndirectDraws (multi_draw.hpp)
// as `draw`, and counts them; `vertex_array` other than 0 replaces the
// scene's (GpuScene::face_vao: ranges of the face stream).
void submit_queued(const DrawContext& ctx, const LevelView& view, const SceneDraw& draw, GLuint vertex_array = 0);

// Instances per range: 2 (both eyes), 1 in two-pass stereo.
int instances_of(const DrawContext& ctx);

// One full-target triangle; or, with `quads` > 0, that many instances of
// clear_depth.vert.glsl's eye rectangles (u_eye_quads).
void draw_full_target(const DrawContext& ctx, const LevelView& view, const TargetDraw& draw, int quads = 0);

// The pixel rectangle (GL window coordinates) covering both eyes' rects.
gl::ScissorRect scissor_of(const DrawContext& ctx, const std::array<NdcRect, 2>& rects, const LevelView& view);

// Where a level's own draws may write: with culling, the pixels of the
// portal it is seen through (LevelView::through_portal); else everywhere.
Scissor level_scissor(const DrawContext& ctx, const LevelView& view);

// Where the draws of a portal of `view` may write: its pixels with culling.
Scissor portal_scissor(const DrawContext& ctx, const LevelView& view, const std::array<NdcRect, 2>& rects);

// Uploads the per-eye uniforms of a draw with `program`: matrices,
// rectangles, planes, relative to the cell's origin.
void set_eye_uniforms(const DrawContext& ctx, const LevelView& view, const SceneProgram& program,
                      const std::array<NdcRect, 2>& rects);

void set_cell_id(const SceneProgram& program, unsigned id, bool unshaded);

// The same for geometry whose vertices are in other coordinates than the
// cell's: `model` maps them to the cell's (layout) coordinates, and the
// checker pattern is at `checker_offset` (composed in double).
void set_model_uniforms(const DrawContext& ctx, const LevelView& view, const SceneProgram& program,
                        const std::array<NdcRect, 2>& rects, const math::dmat4& model, const glm::vec3& checker_offset);

// A kVolumes program's uniforms for a draw in `view` (of a cell with
// volumes): the cell's volumes, the vertices mapped by `to_cell` (vertex →
// cell layout coordinates), and which side of them is kept: inside = -1
// hides the inside of every volume (the cell's own draws), k >= 0 shows the
// inside of volume k only, tinted (its target room's draws). Nothing for a
// program without volumes.
void set_volume_uniforms(const DrawContext& ctx, const LevelView& view, const SceneProgram& program,
                         const math::dmat4& to_cell, int inside);

// Depth as the frame's clip-space z of the far plane (w = 1).
inline float far_depth(const FrameDesc& frame) { return frame.depth == DepthMode::ReversedZ ? 0.0f : 1.0f; }

}  // namespace impossible::render
