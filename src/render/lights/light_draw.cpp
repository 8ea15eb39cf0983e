// A colour pass's lights (light_draw.hpp).
#include "render/lights/light_draw.hpp"

namespace impossible::render {

namespace {

// No lookup can find a prop's shadow: the room's images have no maps, or
// the part of the view's own cell lies outside their shadows' hulls.
bool without_shadows(const DrawContext& ctx, size_t c, const LevelView* view) {
    const std::vector<std::optional<std::vector<std::array<glm::dvec3, 16>>>>& regions = ctx.lights.shadow_regions;
    if (c >= regions.size() || !regions[c]) return false;
    return regions[c]->empty() || (view && view->outside_shadows && static_cast<int>(c) == view->cell);
}

}  // namespace

unsigned light_flags(const DrawContext& ctx, int room, const LevelView* view) {
    if (!ctx.scene.lighting.lit) return 0u;
    const auto c = static_cast<size_t>(room);
    if (ctx.lights.count[c] == 0) return kLights | kLightsAmbient;
    const unsigned shadows = without_shadows(ctx, c, view) ? kLightsNoShadows : 0u;
    if (view && view->outside_light_paths && room == view->cell) {
        if (ctx.lights.direct[c] == 0) return kLights | kLightsAmbient;
        return kLights | (ctx.lights.ubo ? kLightsUbo : 0u) | direct_loop_flags(ctx.lights, room) | shadows;
    }
    return kLights | (ctx.lights.ubo ? kLightsUbo : 0u) | (ctx.frame.naive_lights ? kLightsNaive : 0u) |
           light_loop_flags(ctx.lights, room) | shadows;
}

bool draws_cached(const DrawContext& ctx, int room) {
    const LightCacheGpu& cache = ctx.lights.cache;
    const auto c = static_cast<size_t>(room);
    return ctx.lights.use_cache && c < cache.cached.size() && cache.cached[c];
}

unsigned cached_light_flags(const DrawContext& ctx, int room) {
    const auto c = static_cast<size_t>(room);
    return kLights | kLightsCached | (ctx.lights.ubo ? kLightsUbo : 0u) |
           (ctx.lights.plain_points[c] ? kLightsPlainPoints : 0u) |
           (ctx.lights.direct_blockers[c] ? kLightsDirectBlockers : 0u) |
           (without_shadows(ctx, c, nullptr) ? kLightsNoShadows : 0u);
}

void set_room_lights(const DrawContext& ctx, const SceneProgram& program, int room, bool count) {
    if (!ctx.scene.lighting.lit) return;
    set_light_uniforms(ctx.lights, program, room, glm::mat4(1.0f));
    if (count) ctx.scratch.stats.light_images += ctx.lights.count[static_cast<size_t>(room)];
}

}  // namespace impossible::render
