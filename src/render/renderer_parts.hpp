// Internal to src/render: what a Renderer keeps, by how long it lives.
//
// - SceneData (scene_data.hpp) is fixed for the layout: the scene's tables,
//   its GPU buffers, and what a lit layout gives to make its light images.
//   Made by Renderer::create; drawing a frame only reads it.
// - Programs (programs/programs.hpp): each built before the first frame that
//   needs it (a stereo mode's, a feature's) and never changed after; shared
//   with the other renderers of the context where the caller gave them
//   (renderer.hpp, SharedPrograms).
// - LightState (lights/light_state.hpp): a lit layout's light images on the
//   GPU and the props' shadow maps, remade when a frame's light setting (its
//   light depth, shadows, shadow map size) or its props' places differ from
//   the last frame's.
// - FrameTargets (targets/frame_targets.hpp): what frames are drawn into,
//   remade before a frame that asks for another size, depth mode or sample
//   count.
// - KeptBetweenFrames (below): what one frame leaves to the next.
// - FrameScratch (draw/frame_scratch.hpp): the scratch of one frame.
#pragma once

#include <memory>

#include "gl/state.hpp"
#include "render/draw/frame_scratch.hpp"
#include "render/lights/light_state.hpp"
#include "render/programs/programs.hpp"
#include "render/renderer.hpp"
#include "render/scene_data.hpp"
#include "render/targets/frame_targets.hpp"
#include "walk/prop_walks.hpp"

namespace impossible::render {

// State kept between frames: the moving props walked from frame to frame,
// over SceneData::object_set (a frame walks only the keys passed since the
// last one; walk::PropWalks gives the same states as walking from t = 0).
struct KeptBetweenFrames {
    std::unique_ptr<walk::PropWalks> prop_walks;
};

// All a Renderer owns. It stays where it is (Renderer holds it by pointer):
// the prop walks keep a pointer to scene.object_set.
struct RendererParts {
    gl::StateCache* state = nullptr;  // the context's; outlives the renderer
    SceneData scene;
    SharedPrograms programs;  // never null
    LightState lights;
    FrameTargets targets;
    KeptBetweenFrames kept;
    FrameScratch scratch;
};

}  // namespace impossible::render
