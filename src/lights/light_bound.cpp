// The bound on a frame's light work (light_bound.hpp).
#include "lights/light_bound.hpp"

#include <algorithm>

#include "lights/light_images.hpp"

namespace impossible::lights {

namespace {

// Keeps lights in file order while their own images' rectangles fit.
void lb_drop_lights(const LightWork& work, LightBound& bound) {
    std::size_t left = kMaxLightRects;
    bound.lit_lights = 0;
    for (std::size_t r = 0; r < work.own_rects.size(); ++r) {
        for (std::size_t l = 0; l < work.own_rects[r].size(); ++l) {
            const std::size_t rects = work.own_rects[r][l];
            bound.lit[r][l] = rects <= left;
            if (!bound.lit[r][l]) continue;
            left -= rects;
            ++bound.lit_lights;
        }
    }
}

}  // namespace

LightBound light_bound(const layout::Layout& layout, const links::PortalLinks& links) {
    LightBound bound;
    for (const layout::Room& room : layout.rooms) {
        bound.lit.emplace_back(room.lights.size(), true);
        bound.lights += room.lights.size();
    }
    bound.lit_lights = bound.lights;
    if (layout.lighting != layout::Lighting::Lights) return bound;
    bound.paths_depth = light_depth_within(layout, links, layout::kMaxLightDepth, kMaxLightPaths);
    // Paths, and so rectangles, only grow with the depth: the images of
    // depth d are those of the deepest listing with at most d portals.
    const LightWork work = light_work(layout, links, bound.paths_depth);
    std::size_t rects = 0;
    bound.depth = -1;
    for (int k = 0; k <= bound.paths_depth; ++k) {
        rects += work.rects[static_cast<std::size_t>(k)];
        if (rects > kMaxLightRects) break;
        bound.depth = k;
    }
    if (bound.depth < 0) {
        bound.depth = 0;
        lb_drop_lights(work, bound);
    }
    return bound;
}

LightCut light_cut(const LightBound& bound, int asked) {
    if (bound.lit_lights < bound.lights) return LightCut::Rects;
    if (asked <= bound.depth) return LightCut::None;
    return bound.depth == bound.paths_depth ? LightCut::Paths : LightCut::Rects;
}

std::vector<layout::Light> lit_lights(const layout::Layout& layout, const LightBound& bound, int room) {
    const std::vector<layout::Light>& all = layout.rooms[static_cast<std::size_t>(room)].lights;
    if (bound.lit_lights == bound.lights) return all;
    std::vector<layout::Light> out;
    for (std::size_t l = 0; l < all.size(); ++l)
        if (bound.lit[static_cast<std::size_t>(room)][l]) out.push_back(all[l]);
    return out;
}

layout::Layout with_lit_lights(const layout::Layout& layout, const LightBound& bound) {
    layout::Layout out = layout;
    if (bound.lit_lights == bound.lights) return out;
    for (std::size_t r = 0; r < out.rooms.size(); ++r)
        out.rooms[r].lights = lit_lights(layout, bound, static_cast<int>(r));
    return out;
}

}  // namespace impossible::lights
