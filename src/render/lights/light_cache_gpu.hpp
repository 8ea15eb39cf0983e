// Internal to src/render: the light cache (light_cache.hpp) on the GPU, made
// from a renderer's second frame at a light depth on (a one-frame render
// never pays for it, and draws exactly as without it), and kept with the
// light images it was made from (LightBuffers::cache).
#pragma once

#include <vector>

#include "gl/handles.hpp"

namespace impossible::render {

struct LightCacheGpu {
    bool built = false;
    int map_size = -1;         // the shadow maps' size it was made for (0: no prop shadows)
    int frames_seen = 0;       // frames prepared in a row with these light images and map size, the cache or not
    int seen_map_size = -1;    // those frames' map size
    gl::Texture corners;       // RGBA16F, 2 x 2 texels a cell (kLightCacheUnit)
    gl::Texture edges;         // R32UI, a cell's images added per fragment (kLightEdgesUnit)
    std::vector<bool> cached;  // per room
};

}  // namespace impossible::render
