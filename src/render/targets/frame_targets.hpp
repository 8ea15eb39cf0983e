// Internal to src/render: what a renderer's frames are drawn into
// (frame_targets.cpp), remade before a frame that asks for another size,
// depth mode or sample count. Target itself is render/target.hpp, part of
// the Renderer's interface (Renderer::target).
#pragma once

#include <vector>

#include "base/result.hpp"
#include "gl/state.hpp"
#include "render/frame.hpp"
#include "render/target.hpp"
#include "render/targets/hidden_mask.hpp"
#include "render/targets/multisample.hpp"

namespace impossible::render {

struct FrameTargets {
    Target target;                        // single-sample: what is read back or shown
    Multisampling multisampling;          // with FrameDesc::samples > 1
    std::vector<Target> portal_textures;  // one per portal of the head's cell (render-to-texture portals)
    HiddenMask hidden_mask;               // the frame's hidden areas (headset optics)
};

// `targets.target` of width × height and the depth mode, made again when it
// differs (and with it the multisample resolve's framebuffers, which hold
// the old target's buffers).
Result<void> ensure_frame_target(FrameTargets& targets, int width, int height, DepthMode depth);

// Clears a target to the background colour, id 0, far depth (for its depth
// mode) and the given stencil value, through the state cache.
void clear_target(gl::StateCache& state, const Target& target, int stencil);

}  // namespace impossible::render
