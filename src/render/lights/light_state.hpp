// Internal to src/render: a lit layout's lights as a renderer keeps them
// between frames (light_state.cpp). What the scene gives is fixed
// (SceneLights, scene_data.hpp); what is made from it changes with a frame's
// light setting (View::light_depth; FrameDesc::shadows, shadow_map_size) and
// its props, and is remade only when a frame asks for something else.
#pragma once

#include "render/frame.hpp"
#include "render/lights/light_buffers.hpp"
#include "render/lights/shadow_maps.hpp"

namespace impossible::render {

struct SceneData;

struct LightState {
    LightBuffers buffers;    // the light images of the depth last drawn (ensure_lights)
    ShadowMaps shadow_maps;  // the props' shadows of `buffers` (shadow_maps.hpp)
};

// A lit layout's light images at the frame's light depth on the GPU: the
// scene's, or made for View::light_depth when it differs, and kept until a
// frame asks for another depth. Nothing for a "fixed" layout.
void ensure_lights(LightBuffers& buffers, const SceneData& scene, const FrameDesc& frame);

// The light cache of `buffers` (light_cache_gpu.hpp), made under
// FrameDesc::light_cache from the second frame in a row prepared with them
// and one shadow map size (cache_map_size; a frame of another size starts
// the count again, so frames that alternate sizes draw exactly instead of
// remaking it). Never on the web build.
void ensure_light_cache(LightBuffers& buffers, const SceneData& scene, const FrameDesc& frame);

// The shadow maps' size the frame's cache must be made for (0: no prop shadows).
int cache_map_size(const FrameDesc& frame);

}  // namespace impossible::render
