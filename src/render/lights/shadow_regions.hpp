// Where a frame's shadow maps may shadow anything, per lit room: for each
// light image with a map, each of its occluders' shadow hull
// (lights::shadow_region), in the room's coordinates. Outside all of them
// every image's lookup finds nothing nearer than the point, so a room's
// draws there skip the lookups (object_draw.cpp, LIGHTS_NO_SHADOWS), with
// the same image. Conservative: occluders are taken as their bounding
// boxes, grown by a few map texels (a lookup's nearest texel may hold an
// occluder just beside the direction).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "lights/light_images.hpp"
#include "render/lights/shadow_maps.hpp"

namespace impossible::render {

// How far (radians) an occluder's box is grown for maps of `map_size`
// texels a side: a lookup reads the nearest texel, whose direction is
// within about a texel (2 / size radians at a face's centre, less than
// twice that anywhere) of the point's, so four texels at its far side.
inline double shadow_grow_angle(int map_size) { return 8.0 / (map_size > 1 ? map_size : 1); }

// nullopt where some image may shadow anywhere (a light within an
// occluder's bounds); an empty list where no image of the room has a map.
using RoomShadowRegions = std::optional<std::vector<std::array<glm::dvec3, 16>>>;

// Where a frame's maps are drawn from: the scene's props and the frame's
// placed objects (what prepare_shadow_maps draws).
struct SceneData;
struct FrameObjects;
ShadowSources shadow_sources(const SceneData& r, const FrameObjects& objects);

// The frame's regions for LightBuffers::shadow_regions: none where the
// frame draws lit rooms in one part (FrameDesc::split_light_draws) or does
// not cull portals; an empty list for a room whose images have no map
// (shadows off, say).
std::vector<RoomShadowRegions> frame_shadow_regions(const ShadowMaps& maps, const SceneData& r,
                                                    const FrameObjects& objects,
                                                    const std::vector<lights::RoomLights>& rooms,
                                                    const FrameDesc& frame);

// Per room of `rooms`; `layer` per global image as ShadowMaps::layer,
// `bounds` each room's bounding box (min, max), `map_size` the maps' texels
// per face side.
std::vector<RoomShadowRegions> shadow_regions(const ShadowSources& s, const std::vector<lights::RoomLights>& rooms,
                                              const std::vector<int>& layer,
                                              const std::vector<std::pair<glm::dvec3, glm::dvec3>>& bounds,
                                              int map_size);

}  // namespace impossible::render
