// The light cache made and uploaded (light_state.hpp, ensure_light_cache).
#include <cstddef>
#include <cstdint>

#include "render/lights/light_cache.hpp"
#include "render/lights/light_state.hpp"
#include "render/programs/gpu_scene.hpp"
#include "render/scene_data.hpp"

namespace impossible::render {
#if !defined(__EMSCRIPTEN__)
namespace {

gl::Texture upload_atlas(GLenum internal, int width, int height, GLenum format, GLenum type, const void* data,
                         GLint filter) {
    gl::Texture t = gl::create_texture(GL_TEXTURE_2D);
    glTextureStorage2D(t.get(), 1, internal, width, height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureSubImage2D(t.get(), 0, 0, 0, width, height, format, type, data);
    glTextureParameteri(t.get(), GL_TEXTURE_MIN_FILTER, filter);
    glTextureParameteri(t.get(), GL_TEXTURE_MAG_FILTER, filter);
    glTextureParameteri(t.get(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

}  // namespace
#endif

int cache_map_size(const FrameDesc& frame) {
    return frame.shadows && frame.shadow_map_size > 0 ? frame.shadow_map_size : 0;
}

void ensure_light_cache(LightBuffers& buffers, const SceneData& scene, const FrameDesc& frame) {
#if defined(__EMSCRIPTEN__)
    (void)buffers, (void)scene, (void)frame;
#else
    const SceneLights& l = scene.lighting;
    if (!l.lit || buffers.depth < 0) return;
    LightCacheGpu& cache = buffers.cache;
    const int map_size = cache_map_size(frame);
    if (map_size != cache.seen_map_size) {
        cache.seen_map_size = map_size;
        cache.frames_seen = 0;
    }
    ++cache.frames_seen;
    if (!frame.light_cache || cache.frames_seen < 2 || (cache.built && cache.map_size == map_size)) return;
    LightCacheInput in{.vertices = &l.vertices,
                       .indices = &l.indices,
                       .cells = &scene.cells,
                       .objects = &scene.objects,
                       .origins = &scene.cell_origins,
                       .rooms = &buffers.rooms,
                       .packed_images = &buffers.packed_images,
                       .first = buffers.first,
                       .excluded = {},
                       .bounds = {},
                       .shadow_map_size = map_size};
    for (size_t c = 0; c < buffers.rooms.size(); ++c) {
        in.excluded.push_back(!scene.volumes[c].empty());
        const layout::Room& room = l.lit_layout->rooms[c];
        in.bounds.emplace_back(room.min, room.max);
    }
    const LightCache made = build_light_cache(in);
    cache = LightCacheGpu{};
    cache.frames_seen = 2;
    cache.seen_map_size = cache.map_size = map_size;
    cache.built = true;
    cache.cached = made.cached;
    cache.corners =
        upload_atlas(GL_RGBA16F, 2 * made.width, 2 * made.height, GL_RGBA, GL_FLOAT, made.corners.data(), GL_LINEAR);
    cache.edges =
        upload_atlas(GL_R32UI, made.width, made.height, GL_RED_INTEGER, GL_UNSIGNED_INT, made.edges.data(), GL_NEAREST);
    glNamedBufferSubData(scene.gpu.light_cells.get(), 0,
                         static_cast<GLsizeiptr>(made.vertex_cells.size() * sizeof(glm::vec2)),
                         made.vertex_cells.data());
#endif
}

}  // namespace impossible::render
