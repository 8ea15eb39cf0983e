// The GL renderer: one side-by-side stereo frame of a layout, drawn with
// single-pass instanced stereo and recursive stencil portals.
//
// Needs a current GL 4.5 context (gl/context.hpp). Talks to the rest of the
// program through plain data: a FrameDesc in, an Image and FrameStats out.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gl/state.hpp"
#include "layout/layout.hpp"
#include "render/frame.hpp"
#include "render/gpu_scene.hpp"
#include "render/scene_program.hpp"
#include "render/target.hpp"
#include "scene/scene.hpp"

namespace impossible::render {

struct Renderer {
    layout::Layout layout;
    scene::Scene scene;                   // index ranges of cells and portal boxes
    std::vector<math::dmat4> transfer;    // M_AB per portal A, computed once
    std::vector<std::vector<int>> portals_of_room;
    GpuScene gpu;
    std::optional<SceneProgram> programs[3];  // per StereoMode, built on first use
    ClearDepthProgram clear_depth;
    gl::VertexArray empty_vao;            // for the attribute-less clear triangle
    Target target;
    gl::StateCache state;
    std::vector<gl::Query> mark_queries;  // occlusion queries of portal marks, reused every frame
    std::optional<SceneProgram> portal_texture_program;  // render-to-texture portals, built on first use
    std::vector<Target> portal_textures;  // one per portal of the head's cell, reused every frame
};

struct RendererResult {
    std::unique_ptr<Renderer> renderer;
    std::string error;
};

RendererResult create_renderer(const layout::Layout& layout, const scene::Scene& scene);

struct FrameResult {
    image::Image image;
    FrameStats stats;
    std::string error;  // e.g. a stereo mode the driver cannot do
};

FrameResult render_frame(Renderer& renderer, const FrameDesc& frame);

// Clears a target to the background colour, id 0, far depth (for its depth
// mode) and the given stencil value, through the renderer's state cache.
void clear_target(Renderer& renderer, const Target& target, int stencil);

// Draws without reading back (for timing); same state as render_frame.
std::string draw_frame(Renderer& renderer, const FrameDesc& frame, FrameStats* stats);

}  // namespace impossible::render
