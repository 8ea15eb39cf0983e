// The headless renderers' shared context and bound (headless_share.hpp).
#include "api/headless_share.hpp"

#include <algorithm>
#include <array>

#include "math/view_limits.hpp"
#include "render/lights/shadow_maps.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace impossible::api {
namespace {

// Per thread and backend (Egl, OSMesa): the renderers hold the share, so it
// lives as long as the last of them.
thread_local std::array<std::weak_ptr<HeadlessShare>, 2> shares;

Result<std::shared_ptr<HeadlessShare>> share_for(gl::Backend backend) {
    std::weak_ptr<HeadlessShare>& slot = shares[backend == gl::Backend::Egl ? 0 : 1];
    if (std::shared_ptr<HeadlessShare> share = slot.lock()) return share;
    Result<gl::Context> made = gl::create_context(backend);
    if (!made) return impossible::Error{made.error()};
    auto share = std::make_shared<HeadlessShare>(std::move(*made));
    slot = share;
    return share;
}

// What each renderer keeps of one kind, least recently drawn first, and
// whose it is; without `r`, which drew or draws now.
template <class Amount>
std::vector<std::int64_t> kept_by_others(const std::vector<render::Renderer*>& renderers, const render::Renderer& r,
                                         std::vector<render::Renderer*>& whose, Amount amount) {
    std::vector<std::int64_t> kept;
    for (render::Renderer* other : renderers)
        if (other != &r) {
            kept.push_back(amount(other->kept()));
            whose.push_back(other);
        }
    return kept;
}

}  // namespace

std::size_t releases_needed(const std::vector<std::int64_t>& kept, std::int64_t need, std::int64_t bound) {
    if (need > bound) return 0;
    std::int64_t total = need;
    for (std::int64_t k : kept) total += k;
    std::size_t n = 0;
    for (; n < kept.size() && total > bound; ++n) total -= kept[n];
    return n;
}

Result<std::shared_ptr<HeadlessShare>> HeadlessShare::of_this_thread(std::optional<gl::Backend> requested) {
    if (requested) return share_for(*requested);
    Result<std::shared_ptr<HeadlessShare>> egl = share_for(gl::Backend::Egl);
    if (egl) return egl;
    Result<std::shared_ptr<HeadlessShare>> osmesa = share_for(gl::Backend::OSMesa);
    if (!osmesa) return impossible::Error{egl.error() + "; " + osmesa.error()};
    return osmesa;
}

void HeadlessShare::join(render::Renderer& r) {
    const std::lock_guard lock(mutex_);
    renderers_.push_back(&r);
}

void HeadlessShare::leave(render::Renderer& r) {
    const std::lock_guard lock(mutex_);
    std::erase(renderers_, &r);
}

void HeadlessShare::move_to_back(const render::Renderer& r) {
    const auto at = std::find(renderers_.begin(), renderers_.end(), &r);
    if (at != renderers_.end()) std::rotate(at, at + 1, renderers_.end());
}

void HeadlessShare::before_frame(const render::Renderer& r, std::int64_t frame_samples) {
    const std::lock_guard lock(mutex_);
    std::vector<render::Renderer*> whose;
    const std::vector<std::int64_t> kept =
        kept_by_others(renderers_, r, whose, [](const render::Renderer::Kept& k) { return k.target_samples; });
    const std::size_t n = releases_needed(kept, frame_samples, math::limits::kMaxFrameSamples);
    for (std::size_t i = 0; i < n; ++i) whose[i]->release_targets();
    if (n > 0) return_free_memory();
}

void HeadlessShare::after_frame(const render::Renderer& r) {
    const std::lock_guard lock(mutex_);
    move_to_back(r);
    std::vector<render::Renderer*> whose;
    const std::vector<std::int64_t> kept =
        kept_by_others(renderers_, r, whose, [](const render::Renderer::Kept& k) { return k.shadow_map_bytes; });
    const auto bound = static_cast<std::int64_t>(render::kMaxShadowMapBytes);
    const std::size_t n = releases_needed(kept, r.kept().shadow_map_bytes, bound);
    for (std::size_t i = 0; i < n; ++i) whose[i]->release_shadow_maps();
    if (n > 0) return_free_memory();
}

void return_free_memory() {
#if defined(__GLIBC__)
    malloc_trim(0);
#endif
}

}  // namespace impossible::api
