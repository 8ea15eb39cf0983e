// The bound on a frame's light work (docs/bounded-work.md, "Light paths"
// and "Path rectangles"), in one place for the rasteriser and the tracer,
// so that both cut it at the same point and still agree. A fragment of
// room C sums every light image of C (shaders/lighting.frag.glsl), and for
// each tests its path's rectangles: its apertures and its blockers, up to
// the ~1,000 walls of a non-convex prism room per leg. Rooms allow 1,000
// lights, so the light paths' bound (kMaxLightPaths) alone left a frame
// of one lit star-shaped room at millions of rectangle tests a fragment.
#pragma once

#include <cstddef>
#include <vector>

#include "layout/layout.hpp"
#include "links/portal_links.hpp"

namespace impossible::lights {

// The most path rectangles (apertures and blockers, path_rect_count) the
// light images of a frame have, all rooms together. A fragment tests at
// most this many, besides its images; at 1280×720 on llvmpipe (2 cores)
// each rectangle a fragment tests costs about 20 ms a frame.
inline constexpr std::size_t kMaxLightRects = 1024;

// Where a layout's lighting is cut. `depth` is the deepest light depth whose
// images number at most kMaxLightPaths and have at most kMaxLightRects
// path rectangles together; a frame asking for light depth d is lit at
// min(d, depth). Where even the lights' own images (depth 0) have more
// rectangles than that, the lights are taken in file order (rooms, then
// each room's lights) and each is kept when its own image's rectangles fit
// in what the lights kept before it leave; the others light nothing. A
// layout within both bounds is lit exactly as without them.
struct LightBound {
    int depth = layout::kMaxLightDepth;
    int paths_depth = layout::kMaxLightDepth;  // the deepest within kMaxLightPaths alone
    std::vector<std::vector<bool>> lit;        // per room, per light: whether it lights frames
    std::size_t lights = 0;                    // all rooms' lights
    std::size_t lit_lights = 0;                // those of them that light frames
};

// What cuts a frame that asks for light depth `asked` (the warnings'
// reason): nothing; the light paths' bound (lit at bound.depth); or the
// rectangles' (lit at min(asked, bound.depth), and by bound.lit_lights of
// the lights where some light nothing).
enum class LightCut { None, Paths, Rects };
LightCut light_cut(const LightBound& bound, int asked);

// The bound of a lit layout (for a "fixed" one: depth kMaxLightDepth, every
// light lit). It costs the light path count's up to 16 tries of at most
// kMaxLightPaths + 1 paths, and one listing of at most kMaxLightPaths
// images (without keeping them).
LightBound light_bound(const layout::Layout& layout, const links::PortalLinks& links);

// Room `room`'s lights that light frames, in file order: what both the
// rasteriser's light images and the tracer's light paths are made from.
std::vector<layout::Light> lit_lights(const layout::Layout& layout, const LightBound& bound, int room);

// The layout with only the lights that light frames (the rasteriser's copy).
layout::Layout with_lit_lights(const layout::Layout& layout, const LightBound& bound);

}  // namespace impossible::lights
