// Internal to src/render: the light images of a lit layout (layout-format.md,
// "Lights"; lights::light_images) as the LIGHTS shaders read them
// (shaders/lighting.frag.glsl): every room's images in one shader storage
// buffer, their paths' portal rectangles in another, positions relative to
// each room's cell origin (scene::CellOrigin) so that float keeps its
// precision far from the layout's origin.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "gl/handles.hpp"
#include "lights/light_images.hpp"
#include "render/lights/light_cache_gpu.hpp"
#include "render/programs/scene_program.hpp"
#include "scene/scene.hpp"

namespace impossible::render {

// One light depth's images on the GPU. The global index of image i of room C
// is first[C] + i (the images of the rooms before C, then i).
struct LightBuffers {
    int depth = -1;  // the light depth they were made for; -1: none
    gl::Buffer images;
    gl::Buffer rects;
    std::vector<int> first;                 // per room
    std::vector<int> count;                 // per room
    std::vector<int> direct;                // per room: its first images, with no apertures (its own lights)
    std::vector<bool> direct_blockers;      // per room: some of them has blockers
    std::vector<bool> plain_points;         // per room: every image a point light without a range
    std::vector<bool> single_apertures;     // per room: every path image one aperture, no blocker
    std::vector<glm::vec3> ambient;         // per room
    std::vector<glm::dvec3> origins;        // per room: its cell origin
    int total = 0;                          // images of every room
    std::vector<lights::RoomLights> rooms;  // the images themselves (the shadow maps')
    std::vector<float> packed_images;       // `images` as uploaded (the light cache's terms)
    // Per room, where its path images (after its direct ones) may light it
    // (lights::lit_region): a truncated pyramid each (none for an image that
    // lights nothing of it); nullopt where some path image may light all of
    // the room.
    std::vector<std::optional<std::vector<std::array<glm::dvec3, 8>>>> path_regions;
    bool ubo = false;  // both fit kLightUboVec4s: bound as uniform blocks (kLightsUbo variants)
    // Per room, this frame's: where its images' shadow maps may shadow a
    // point (render/lights/shadow_regions.hpp); empty while none is known.
    std::vector<std::optional<std::vector<std::array<glm::dvec3, 16>>>> shadow_regions;
    // The light cache of these images (light_cache_gpu.hpp), and whether
    // this frame draws with it (FrameDesc::light_cache; a frame that places
    // no object, whose shadows the cache does not know).
    LightCacheGpu cache;
    bool use_cache = false;
};

// The GPU layout of the images: kLightImageVec4s vec4s per image, 4 per rectangle.
inline constexpr int kLightImageVec4s = 6;
inline constexpr int kLightRectVec4s = 4;

// The images and rectangles packed as shaders/lighting.frag.glsl reads them.
struct PackedLights {
    std::vector<float> images;
    std::vector<float> rects;
};
PackedLights pack_light_images(const std::vector<lights::RoomLights>& rooms, const layout::Layout& layout,
                               const std::vector<scene::CellOrigin>& origins);

// Packs and uploads `rooms` (one per room, in room order) for `depth`; the
// lights themselves (colour, intensity, range, cone) are the layout's.
LightBuffers upload_light_images(const std::vector<lights::RoomLights>& rooms, const layout::Layout& layout,
                                 const std::vector<scene::CellOrigin>& origins, int depth);

// The loop variant's bits for `room`'s images (kLightsNoDirect,
// kLightsNoPaths, kLightsDirectBlockers, kLightsPlainPoints,
// kLightsSingleAperture): 0 where it has both kinds, its own lights meet no
// blocker, some image is a spot or has a range and some path image has more
// than one rectangle; or where it has no image.
unsigned light_loop_flags(const LightBuffers& buffers, int room);
// The same for the room's draws without its path loop (outside where its
// path images may light it): its direct loop alone.
unsigned direct_loop_flags(const LightBuffers& buffers, int room);
// Which loop variants the rooms need (VariantNeeds::light_loops); `shadows`:
// the frame has shadow maps; `split`: the frame's lit rooms may be split by
// where their paths and the props' shadows reach (kLightsNoShadows drawn
// outside the shadows, and everywhere without maps).
std::uint64_t light_loops_needed(const LightBuffers& buffers, bool shadows, bool split);

// Binds the buffers at kLightImagesBinding and kLightRectsBinding (null: unbinds).
void bind_light_buffers(const LightBuffers* buffers);

// A kLights program's uniforms for a draw of surfaces of `room` whose
// vertices `to_light_space` maps into room's coordinates less its cell origin
// (the identity for the room's own cell). Nothing for a program without them.
void set_light_uniforms(const LightBuffers& buffers, const SceneProgram& program, int room,
                        const glm::mat4& to_light_space);

}  // namespace impossible::render
