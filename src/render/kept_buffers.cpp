// What a renderer keeps between frames, counted and released
// (Renderer::kept, release_targets, release_shadow_maps): for a program with
// many renderers in one context, which bounds what they keep together
// (api/headless_share.hpp). A frame finds what it needs gone as it finds it
// of another size, and makes it again: ensure_frame_target, ensure_multisampled,
// ensure_portal_textures and the shadow maps' storage test for that.
#include "render/renderer.hpp"
#include "render/renderer_parts.hpp"

namespace impossible::render {
namespace {

std::int64_t samples_of(const Target& t) {
    if (!t.framebuffer) return 0;
    return std::int64_t{t.width} * t.height * t.samples;
}

}  // namespace

Renderer::Kept Renderer::kept() const {
    Kept k;
    const FrameTargets& targets = parts_->targets;
    k.target_samples = samples_of(targets.target);
    for (const Target& t : targets.multisampling.targets) k.target_samples += samples_of(t);
    for (const Target& t : targets.portal_textures) k.target_samples += samples_of(t);
    const ShadowMaps& maps = parts_->lights.shadow_maps;
    if (maps.maps) {
        const std::int64_t face = std::int64_t{maps.size} * maps.size * 4;  // R32F, and the DEPTH32F face
        k.shadow_map_bytes = face * (6 * std::int64_t{maps.capacity} + 1);
    }
    return k;
}

void Renderer::release_targets() {
    // Nothing of any renderer stays bound between frames (each frame ends
    // with release_bindings), so the cache holds none of these names.
    FrameTargets& targets = parts_->targets;
    targets.target = {};
    targets.multisampling.targets.clear();
    // They hold the frame target's buffers; made again with it.
    targets.multisampling.colour_out = {};
    targets.multisampling.ids_out = {};
    targets.portal_textures.clear();
}

void Renderer::release_shadow_maps() {
    ShadowMaps& maps = parts_->lights.shadow_maps;
    maps.maps = {};
    maps.depth = {};
    // A texture deleted while attached to a framebuffer that is not bound
    // lives on until the framebuffer lets it go: the framebuffer goes too.
    maps.framebuffer = {};
    maps.size = 0;
    maps.capacity = 0;
    maps.keys.clear();  // every map is drawn again
}

}  // namespace impossible::render
