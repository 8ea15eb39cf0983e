// The programs of the renderer (shaders/*.glsl), each with its uniform
// locations looked up once, when it is built: a uniform that the variant
// uses and the program lacks (misspelt, or gone from the shader) fails the
// build with its name and the shaders' (gl::UniformLocations).
#pragma once

#include "base/result.hpp"
#include "gl/handles.hpp"
#include "gl/shader.hpp"
#include "render/frame.hpp"

namespace impossible::render {

// A shader stage compiled into the binary (base/embedded.hpp), named by its path.
gl::ShaderSource embedded_shader(GLenum stage, const char* name);

// The scene's vertex shader with a fragment shader. A location is -1 where
// the variant has no such uniform, and is then never set; the exception is
// checker_offset, which the portal texture's fragment shader does not read,
// so that the compiler may drop it there (setting -1 does nothing).
struct SceneProgram {
    gl::Program program;
    GLint view_proj = -1;       // mat4[2]
    GLint eye_rect = -1;        // vec4[2]
    GLint clip_plane = -1;      // vec4[2]
    GLint checker_offset = -1;  // vec3
    GLint single_eye = -1;      // int, two-pass stereo only
    GLint cell_id = -1;         // uint, scene.frag.glsl only
    GLint unshaded = -1;        // bool, scene.frag.glsl only
    GLint exposure = -1;        // float 2^EV, scene.frag.glsl only (set each frame; 1 when built)
    GLint textured = -1;        // bool: multiply by the texture on kSceneTextureUnit (materials only)
    GLint alpha_cutoff = -1;    // float: drop fragments whose alpha is below it; < 0: opaque (materials only)
    GLint mip_level0 = -1;      // bool: textures at mip level 0 only (materials only)
    GLint target_size = -1;     // vec2, only in the portal-texture program
    GLint record_base = -1;     // kObjectCuts only: int, the record of slot 0 (render/objects/instance_stream.hpp)
    // kVolumes variants only (shaders/scene.frag.glsl, VOLUMES):
    GLint to_volume_space = -1;  // mat4: vertex → the cell's coordinates less its origin
    GLint volume_first = -1;     // int: the cell's first box in the buffer at kVolumeBinding
    GLint volume_count = -1;     // int
    GLint volume_inside = -1;    // int: -1 hide inside every volume; k show inside volume k only
    GLint volume_tint = -1;      // vec3
    // kLights variants only (shaders/lighting.frag.glsl, LIGHTS):
    GLint to_light_space = -1;  // mat4: vertex → the lit room's coordinates less its origin
    GLint light_first = -1;     // int: the lit room's first image in the buffer at kLightImagesBinding
    GLint light_count = -1;     // int
    GLint light_direct = -1;    // int: of them, the first with no apertures (the room's own lights)
    GLint light_ambient = -1;   // vec3: the lit room's ambient
    GLint light_origin = -1;    // vec3: the lit room's cell origin
};

// The texture units of the light cache's atlas (kLightsCached variants).
inline constexpr GLuint kLightCacheUnit = 5;
inline constexpr GLuint kLightEdgesUnit = 6;

// The shader storage buffer binding of every room's volume boxes.
inline constexpr GLuint kVolumeBinding = 3;
// The shader storage buffer bindings of every room's light images and of
// their paths' rectangles (render/lights/light_buffers.hpp).
inline constexpr GLuint kLightImagesBinding = 4;
inline constexpr GLuint kLightRectsBinding = 5;

// What a variant of the scene program adds to the plain one: bits of
// build_scene_variant's `flags`.
inline constexpr unsigned kMaterials = 1u;     // MATERIALS: textures and cut-outs
inline constexpr unsigned kObjectCuts = 2u;    // OBJECT_CUTS: instances of dynamic objects, per-instance records
inline constexpr unsigned kVolumes = 4u;       // VOLUMES: the draws of a cell with volume portals
inline constexpr unsigned kLights = 8u;        // LIGHTS: the colour passes of a lit layout ("lighting": "lights")
inline constexpr unsigned kLightsUbo = 16u;    // with kLights: the light buffers as uniform blocks (LIGHT_UBO)
inline constexpr unsigned kLightsNaive = 32u;  // with kLights: no portal tests (FrameDesc::naive_lights)
// with kLights (alone: no kLightsUbo, no kLightsNaive): a room no light image
// reaches, lit by its ambient alone (LIGHTS_AMBIENT)
inline constexpr unsigned kLightsAmbient = 64u;
// with kLights, the loops over a room's images (lighting.frag.glsl,
// light_sum): its direct images (its own lights, no apertures) and its path
// images (through portals). A room with no direct image (LIGHTS_NO_DIRECT)
// or none through portals (LIGHTS_NO_PATHS) draws without that loop, since
// llvmpipe pays for a loop it skips; LIGHTS_DIRECT_BLOCKERS: some direct
// image has blockers (a free-standing door, a wall of an L-shaped room), so
// the direct loop tests them.
inline constexpr unsigned kLightsNoDirect = 128u;
inline constexpr unsigned kLightsNoPaths = 256u;
inline constexpr unsigned kLightsDirectBlockers = 512u;
// with kLights: no shadow-map lookups (LIGHTS_NO_SHADOWS), where no prop's
// shadow can fall (render/lights/shadow_regions.hpp) or no image has a map.
inline constexpr unsigned kLightsNoShadows = 1024u;
// with kLights: every image of the room is a point light without a range
// (LIGHTS_PLAIN_POINTS): its term has no spot cone and no range falloff,
// whose factors would be exactly 1.
inline constexpr unsigned kLightsPlainPoints = 2048u;
// with kLights: every path image of the room passes one aperture and meets
// no blocker (LIGHTS_SINGLE_APERTURE, a door's light): its test is that one
// crossing, without the loop over rectangles and the blockers' bookkeeping.
inline constexpr unsigned kLightsSingleAperture = 4096u;
inline constexpr unsigned kLightLoopBits = kLightsNoDirect | kLightsNoPaths | kLightsDirectBlockers | kLightsNoShadows |
                                           kLightsPlainPoints | kLightsSingleAperture;
// with kLights: the light cache (render/lights/light_cache.hpp,
// LIGHTS_CACHED): the cached sum at the fragment's cell, and the images its
// bits name added exactly. Only kLightsUbo, kLightsPlainPoints,
// kLightsNoShadows and kLightsDirectBlockers go with it.
inline constexpr unsigned kLightsCached = 8192u;
inline constexpr unsigned kSceneVariantCount = 16384u;
// The loop, shadow and light-kind bits of `flags` as a number 0..63
// (VariantNeeds::light_loops, 64 bits).
inline constexpr unsigned light_loop_index(unsigned flags) { return (flags & kLightLoopBits) / kLightsNoDirect; }

// The vec4s of each light buffer's uniform block (kLightsUbo): 64 KiB, the
// least GL_MAX_UNIFORM_BLOCK_SIZE GL 4.5 allows. Larger light buffers are
// read as shader storage.
inline constexpr int kLightUboVec4s = 4096;

// `materials`: the variant that reads textures and drops cut-out fragments
// (shaders/scene.frag.glsl, MATERIALS), for batches that need it.
Result<SceneProgram> build_scene_program(StereoMode mode, bool materials = false);

// Any variant (`flags` of kMaterials, kObjectCuts, kVolumes, kLights).
Result<SceneProgram> build_scene_variant(StereoMode mode, unsigned flags);

// The scene's vertex shader with shaders/portal_texture.frag.glsl: a portal
// box that shows a render-to-texture view (clip-shift stereo only); with
// `volumes` its VOLUMES variant, for a head's cell with volumes.
Result<SceneProgram> build_portal_texture_program(bool volumes = false);

// A program that writes far depth (0 in reversed-Z) over the whole target and
// nothing else; with the stencil test it clears depth inside a portal.
struct ClearDepthProgram {
    gl::Program program;
    GLint far_depth = -1;  // float: clip-space z of the far plane (w = 1)
    GLint color = -1;      // vec4: the colour it writes where colour is not masked (id 0)
    GLint eye_quads = -1;  // bool: one rectangle per instance instead of the full target
    GLint rects = -1;      // vec4[2]: those rectangles
};

Result<ClearDepthProgram> build_clear_depth_program();

// The full-target triangle of a window's blend (shaders/window_blend.frag.glsl):
// r · the reflected view copied aside, added to the colour by the blend.
struct WindowBlendProgram {
    gl::Program program;
    GLint use_saved = -1;  // bool
    GLint scale = -1;      // vec3: r
    GLint constant = -1;   // vec3: r · fill colour, without a copy
};

// `multisample`: the copy is a multisample texture, read per sample.
Result<WindowBlendProgram> build_window_blend_program(bool multisample);

// The id resolve of a multisampled target (shaders/id_resolve.frag.glsl,
// render/targets/multisample.hpp) for `samples` samples, reading texture unit 0.
Result<gl::Program> build_id_resolve_program(int samples);

}  // namespace impossible::render
