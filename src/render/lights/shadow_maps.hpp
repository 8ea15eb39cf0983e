// Cube shadow maps of the props' shadows under "lighting": "lights"
// (layout-format.md, "Lights"; docs/lighting.md, "Shadows").
//
// One cube map per light image g (lights::light_images, every room's images
// flattened in room order: room 0's, then room 1's, ...) whose path has props:
// face texel by face texel, the distance |q - L'| from the image's position
// L' (in the lit room C's coordinates) to the nearest prop surface q, or
// kNoShadowOccluder. The occluders of an image are, for each leg i of its
// path, that leg's room's props, static and dynamic (moving props, crossing
// objects with their door cuts, hands), mapped into C's coordinates by
// inverse(to_room[i]) and clipped to the leg's slab: leg 0 in front of
// aperture 0's plane, leg i behind aperture i-1's and in front of aperture
// i's, the last behind the last aperture's. Room faces are not occluders
// (the shader's aperture test handles rooms exactly); alpha cut-outs are
// (their texel's alpha at mip level 0, as the tracer reads it).
//
// The lit fragment shader reads them with shaders/shadow_lookup.frag.glsl:
// light_visible(g, p - L', |p - L'|), bound by bind_shadow_maps (the cube map
// array on kShadowMapTextureUnit, the per-image layers at kShadowLayerBinding).
//
// Maps are drawn again only for what changed: an image's map is kept while
// its inputs (its position and path, the placements of the dynamic objects in
// its legs' rooms, the map size) are the same as when it was drawn, so a
// static lit layout draws its maps in its first frame only.
#pragma once

#include <cstddef>
#include <vector>

#include "base/result.hpp"
#include "gl/handles.hpp"
#include "gl/state.hpp"
#include "lights/light_images.hpp"
#include "render/frame.hpp"
#include "render/programs/gpu_scene.hpp"
#include "scene/scene.hpp"
#include "walk/objects.hpp"

namespace impossible::render {

// The texture unit of the cube map array (shadow_lookup.frag.glsl's
// layout(binding = 3)) and the shader storage binding of the per-image
// layers (its layout(binding = 6); 4 and 5 are the light buffers').
inline constexpr GLuint kShadowMapTextureUnit = 3;
inline constexpr GLuint kShadowLayerBinding = 6;

// What a texel with no prop in its direction holds.
inline constexpr float kNoShadowOccluder = 3.0e38f;

// The maps' memory (6 · size² · 4 bytes per map) is kept under this by
// halving the size (not below kMinShadowMapSize).
inline constexpr std::size_t kMaxShadowMapBytes = std::size_t{256} << 20;
inline constexpr int kMinShadowMapSize = 16;

// Occluders nearer than this to a light's image are not drawn (a light
// inside a prop is still inside it: its faces are farther).
inline constexpr double kShadowNear = 1e-4;

// The lookup's constant bias, in texels of the map at the point's distance
// (shadow_lookup.frag.glsl adds 0.75 texel per unit of tan(incidence), and a
// relative 1e-5 for float32): where a prop's shadow may start short of its
// contact with a surface lit head-on.
inline constexpr double kShadowBiasTexels = 0.5;

// The size a frame's maps are drawn at: the requested size, halved until
// `maps` maps fit in kMaxShadowMapBytes. A frame has at most
// GL_MAX_ARRAY_TEXTURE_LAYERS / 6 maps (341 on llvmpipe and most drivers):
// the images past them (in the global order) have none, and light passes
// their props.
int shadow_map_size_for(int requested, std::size_t maps);

// Where the maps' occluders are drawn from (the scene's data and the
// frame's placed objects; object_draw.cpp draws the same).
struct ShadowSources {
    const GpuScene* gpu = nullptr;
    const std::vector<scene::CellObjects>* objects = nullptr;  // per room: static props' batches
    const std::vector<scene::CellOrigin>* origins = nullptr;   // per room
    const std::vector<scene::ObjectMesh>* object_meshes = nullptr;
    const std::vector<walk::ObjectInstance>* instances = nullptr;  // the frame's (walk::place_objects)
    const std::vector<int>* instance_mesh = nullptr;               // per instance: its object mesh
};

struct ShadowMaps {
    gl::Texture maps;   // GL_TEXTURE_CUBE_MAP_ARRAY, R32F, layer-face 6 · layer + face
    gl::Texture depth;  // DEPTH32F, one face's
    gl::Framebuffer framebuffer;
    gl::Buffer layers;  // std430 { float texel; float bias_texels; int layer[images]; }
    gl::Program program;
    GLint model = -1, face_proj = -1, planes = -1, textured = -1, alpha_cutoff = -1;
    int size = 0;                           // texels per face side of `maps`
    int capacity = 0;                       // cube maps `maps` holds
    int max_maps = 0;                       // GL_MAX_ARRAY_TEXTURE_LAYERS / 6 (0: not asked yet)
    std::vector<int> layer;                 // per global image: its cube map, or -1 (no props, or shadows off)
    std::vector<std::vector<double>> keys;  // per cube map: what it was drawn from
};

// Draws the maps that changed since they were last drawn and fills the
// layer buffer; returns the number of cube maps drawn. Shadows off (or a
// size of 0): no maps, every image's layer -1. Changes the draw
// framebuffer, viewport, program and pass state through `state`.
Result<int> update_shadow_maps(ShadowMaps& maps, gl::StateCache& state, const ShadowSources& sources,
                               const std::vector<lights::RoomLights>& rooms, const FrameDesc& frame);

// Binds the maps and the layer buffer for the lit shader.
void bind_shadow_maps(const ShadowMaps& maps, gl::StateCache& state);
// Unbinds the layer buffer (the texture unit goes with the cache's
// release_bindings).
void unbind_shadow_maps();

// The renderer's part, once a frame of a lit layout, after the frame's
// objects are placed and before its passes: updates the maps from the
// scene's data, the frame's objects and `rooms` (the light images of the
// frame's light depth, those the lit shader's global indices count), counts
// the maps drawn in stats.shadow_maps_drawn and binds them.
struct SceneData;
struct FrameObjects;
Result<void> prepare_shadow_maps(ShadowMaps& maps, gl::StateCache& state, const SceneData& r,
                                 const FrameObjects& objects, const std::vector<lights::RoomLights>& rooms,
                                 const FrameDesc& frame, FrameStats& stats);

}  // namespace impossible::render
