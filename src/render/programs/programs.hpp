// Internal to src/render: every program a renderer draws with, each built
// before the first frame that needs it and never changed after
// (programs.cpp); the shaders' sources and their loader are
// scene_program.hpp's.
#pragma once

#include <cassert>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "base/result.hpp"
#include "gl/handles.hpp"
#include "render/frame.hpp"
#include "render/programs/scene_program.hpp"

namespace impossible::render {

inline constexpr int kStereoModeCount = 3;

inline int mode_index(StereoMode mode) {
    const int i = static_cast<int>(mode);
    assert(i >= 0 && i < kStereoModeCount);
    return i;
}

// Every program a renderer draws with.
struct Programs {
    std::optional<SceneProgram> scene[kStereoModeCount];     // per StereoMode
    std::optional<SceneProgram> material[kStereoModeCount];  // the same with textures and cut-outs
    std::optional<SceneProgram> portal_texture;              // render-to-texture portals
    // The variants with kObjectCuts or kVolumes (scene_program.hpp), per
    // StereoMode and flags, built before the first frame that needs them.
    // A map, not an array of kSceneVariantCount: a frame needs a few of them
    // (a renderer's memory, tests/python/test_memory.py).
    std::map<unsigned, SceneProgram> variants[kStereoModeCount];
    std::optional<SceneProgram> portal_texture_volumes;  // render-to-texture portals of a cell with volumes
    std::optional<WindowBlendProgram> window_blend[2];   // single-sample, multisample copies
    std::vector<gl::Program> id_resolve;                 // the multisample id resolve per sample count (index: count)
    ClearDepthProgram clear_depth;                       // built with the renderer
    gl::VertexArray empty_vao;                           // for the attribute-less full-target triangle
};

// The stereo mode's scene program (or its material one), built once; a
// mode the driver lacks is an error naming what it needs.
Result<void> ensure_scene_program(Programs& programs, StereoMode mode, bool materials);

// What the variants a frame may draw with depend on.
struct VariantNeeds {
    bool objects = false;       // dynamic objects or hands: kObjectCuts
    bool volumes = false;       // some room has a volume: kVolumes
    bool lit = false;           // "lighting": "lights": kLights
    bool lights_ubo = false;    // the frame's light buffers are uniform blocks: kLightsUbo (else storage)
    bool lights_naive = false;  // FrameDesc::naive_lights: kLightsNaive
    bool materials = false;     // some batch has a texture or a cutoff: kMaterials
    // The light loop variants some room may draw with (light_loop_flags):
    // bit light_loop_index(flags) of each.
    std::uint64_t light_loops = 0u;
    bool light_cache = false;  // the light cache is built: kLightsCached
};

// The variants with object cuts, volumes or lights (scene_program.hpp) that
// a frame of `mode` may draw with.
Result<void> ensure_variants(Programs& programs, StereoMode mode, const VariantNeeds& needs);

}  // namespace impossible::render
