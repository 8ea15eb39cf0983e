// The programs a renderer builds as frames need them (programs.hpp).
#include "render/programs/programs.hpp"

namespace impossible::render {

Result<void> ensure_scene_program(Programs& programs, StereoMode mode, bool materials) {
    std::optional<SceneProgram>& slot = (materials ? programs.material : programs.scene)[mode_index(mode)];
    if (slot) return {};
    Result<SceneProgram> built = build_scene_program(mode, materials);
    if (!built) {
        if (mode == StereoMode::ViewportIndex)
            return Error{"stereo mode 'viewport-index' needs GL_ARB_shader_viewport_layer_array: " + built.error()};
        return built;
    }
    slot = std::move(*built);
    return {};
}

Result<void> ensure_variants(Programs& programs, StereoMode mode, const VariantNeeds& needs) {
    for (unsigned flags = 0; flags < kSceneVariantCount; ++flags) {
        if ((flags & (kObjectCuts | kVolumes | kLights)) == 0u) continue;
        if (((flags & kObjectCuts) && !needs.objects) || ((flags & kVolumes) && !needs.volumes)) continue;
        if ((flags & kLights) && !needs.lit) continue;
        // The light buffers' kind for the frame's light depth (ensure_lights).
        if ((flags & kLightsUbo) && (!(flags & kLights) || !needs.lights_ubo)) continue;
        if ((flags & kLightsAmbient) && (!(flags & kLights) || (flags & (kLightsUbo | kLightsNaive)))) continue;
        if ((flags & kLights) && !(flags & (kLightsUbo | kLightsAmbient)) && needs.lights_ubo) continue;
        if ((flags & kMaterials) && !needs.materials) continue;
        if ((flags & kLightsNaive) && (!(flags & kLights) || !needs.lights_naive)) continue;
        if (flags & kLightsCached) {
            // The cache's variants: with or without the lookups, and
            // kLightsUbo, kLightsPlainPoints, kLightsDirectBlockers as the
            // room needs.
            constexpr unsigned kCacheBits =
                kLights | kLightsCached | kLightsUbo | kLightsPlainPoints | kLightsNoShadows | kLightsDirectBlockers;
            if (!needs.light_cache || !(flags & kLights) || (flags & ~kCacheBits) != 0u) continue;
        } else if (flags & kLights && !(flags & kLightsAmbient)) {
            if ((needs.light_loops & (std::uint64_t{1} << light_loop_index(flags))) == 0u) continue;
        } else if (flags & kLightLoopBits) {
            continue;
        }
        std::map<unsigned, SceneProgram>& built_ones = programs.variants[mode_index(mode)];
        if (built_ones.contains(flags)) continue;
        Result<SceneProgram> built = build_scene_variant(mode, flags);
        if (!built) return built;
        built_ones.emplace(flags, std::move(*built));
    }
    return {};
}

}  // namespace impossible::render
