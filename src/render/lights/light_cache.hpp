// Internal to src/render: a lit layout's light on its still, flat surfaces,
// cached (docs/lighting.md, "The light cache"). Every plane of a cacheable
// room's faces and box props is a chart of square cells in one atlas; per
// cell, the sum of the light images that reach all of it, unshadowed, at
// its four corners (interpolated bilinearly inside it, LIGHTS_CACHED), and a
// bit for each image whose aperture edge, blocker edge or prop shadow may
// cross it, whose terms the fragment adds exactly, as without the cache.
// The build is pure: no GL context.
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "lights/light_images.hpp"
#include "scene/scene.hpp"

namespace impossible::render {

struct LightCacheInput {
    const std::vector<scene::Vertex>* vertices = nullptr;
    const std::vector<std::uint32_t>* indices = nullptr;
    const std::vector<std::vector<scene::DrawBatch>>* cells = nullptr;  // per room: its batches
    const std::vector<scene::CellObjects>* objects = nullptr;           // per room: its still props (shadows)
    const std::vector<scene::CellOrigin>* origins = nullptr;            // per room
    const std::vector<lights::RoomLights>* rooms = nullptr;             // per room: its light images
    // The images packed as the shaders read them (pack_light_images), and
    // each room's first image among them.
    const std::vector<float>* packed_images = nullptr;
    std::vector<int> first;
    std::vector<bool> excluded;                             // per room: never cached (a room with volumes)
    std::vector<std::pair<glm::dvec3, glm::dvec3>> bounds;  // per room: its box (the shadows' reach)
    int shadow_map_size = 0;                                // 0: no prop shadows
};

struct LightCache {
    int width = 0, height = 0;  // the atlas, in cells
    // Per cell (row after row), RGBA per corner: texel (2x + i, 2y + j) is
    // corner (i, j) of cell (x, y); alpha unused.
    std::vector<float> corners;
    std::vector<std::uint32_t> edges;  // per cell: bit i, image i of its room added per fragment
    // Per scene vertex: its place in the atlas, in cells; (-1, -1) where none.
    std::vector<glm::vec2> vertex_cells;
    std::vector<bool> cached;             // per room
    long cell_count = 0, edge_cells = 0;  // cells, and those with bits
};

// A chart's cell side: a twentieth of the nearest image's distance to it
// (the bilinear error of a point light's term over a cell stays under
// about 0.2 %), within these bounds; larger where the atlas would pass
// kLightCacheMaxCells.
inline constexpr double kLightCacheMinCell = 0.02;
inline constexpr double kLightCacheMaxCell = 0.25;
inline constexpr long kLightCacheMaxCells = 1L << 19;
inline constexpr int kLightCacheAtlasWidth = 1024;      // cells
inline constexpr int kLightCacheAtlasMaxHeight = 8192;  // cells: 16384 texels, GL 4.5's least largest texture
inline constexpr int kLightCacheMaxImages = 32;         // a room's, for one 32-bit mask
// A room of fewer images is drawn exactly, per fragment: on llvmpipe the
// cache's read and its loops cost more than two or three images' terms
// (bench/README.md, "Lights: the light cache").
inline constexpr int kLightCacheMinImages = 4;
// A room whose images have more blockers and prop shadows than this, all
// together, is drawn exactly: every cell is tested against each (a bound on
// the build's time, docs/bounded-work.md).
inline constexpr int kLightCacheMaxTests = 512;

// Which rooms can be cached, their charts and cells. A room is cached when
// it has kLightCacheMinImages to kLightCacheMaxImages light images, whose
// path images each pass one aperture and meet no blocker (its own lights may
// meet blockers), at most kLightCacheMaxTests blockers and prop shadows in
// all; no textured or cut-out batch; every triangle flat (its
// vertices' normals its face's) and no vertex shared by two planes.
LightCache build_light_cache(const LightCacheInput& in);

}  // namespace impossible::render
