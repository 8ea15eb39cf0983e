// One level of the portal recursion: the cell being drawn and, per eye, the
// (virtual) camera, its clip plane and the part of the eye image it may touch.
#pragma once

#include <algorithm>
#include <array>

#include "math/portal.hpp"
#include "math/pose.hpp"

namespace impossible::render {

// A rectangle in an eye's normalised device coordinates (-1..1, y up).
struct NdcRect {
    double x0 = -1, y0 = -1, x1 = 1, y1 = 1;
    bool empty() const { return !(x0 < x1 && y0 < y1); }
    static NdcRect none() { return {1, 1, -1, -1}; }
};

inline NdcRect intersect(const NdcRect& a, const NdcRect& b) {
    return {std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
}

// The bounding rectangle of both (either may be empty).
inline NdcRect united(const NdcRect& a, const NdcRect& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

// `r` grown by `px` pixels on every side, for an eye image of width × height
// pixels. The margins of a level (how far its draws and its culling may
// reach past a portal's rectangle) are in pixels, set where they are used.
inline NdcRect widened(const NdcRect& r, double px, int width, int height) {
    const double mx = 2.0 * px / width, my = 2.0 * px / height;
    return {r.x0 - mx, r.y0 - my, r.x1 + mx, r.y1 + my};
}

struct EyeView {
    bool active = false;
    math::Eye eye;                       // in the cell's coordinates
    math::dmat4 view_proj{1.0};          // cell coordinates → clip space
    math::dvec4 clip_plane{0, 0, 0, 1};  // keep dot(plane, (p, 1)) >= 0
    NdcRect rect;                        // where this level is visible
    bool behind_exit = false;            // the eye stands behind the portal it came out of
    // That portal's plane while behind_exit, in either clip mode (with
    // ClipMode::Oblique clip_plane stays unset: the projection clips).
    math::dvec4 exit_plane{0, 0, 0, 1};
};

struct LevelView {
    int cell = 0;
    int level = 0;          // portals passed; also the stencil value
    int entered_by = -1;    // the portal of this cell the view came out of (or a mirror's), or -1
    bool mirrored = false;  // an odd number of reflections: triangles wind the other way
    double weight = 1.0;    // shading::kMinBranchWeight: the share of this view in the pixels
    // Seen through a portal drawn in the same target, so drawn only within
    // the portal's pixels (its scissor, with culling); false at the root of
    // a target (the head's view, a render-to-texture portal's view).
    bool through_portal = false;
    // The level's surfaces set the stencil's box bit where they hide a
    // portal's box (passes.hpp): only while it has visible portals.
    bool box_bits = false;
    // Its eyes' rectangles hold no volume of its cell (object_draw.hpp,
    // draw_level_colour): drawn by the variants without VOLUMES.
    bool outside_volumes = false;
    // Its eyes' rectangles hold no point that a path image of its cell's
    // lights may reach (draw_level_colour): drawn by the variant without the
    // path loop, or by the ambient one where the cell has no direct image.
    bool outside_light_paths = false;
    // Nor any point a prop's shadow may fall on (render/lights/shadow_regions.hpp):
    // drawn without the shadow-map lookups (LIGHTS_NO_SHADOWS).
    bool outside_shadows = false;
    std::array<EyeView, 2> eyes;
};

// Whether a rectangle of an eye's image of width × height pixels holds the
// centre of a pixel, within 1/256 pixel: llvmpipe snaps vertices to 1/256
// pixel (to the nearest step, so at most 1/512 away), which leaves 1/512
// pixel for single-precision error in the vertex transform. A portal whose rectangle holds none covers no
// pixel: the rasteriser makes no fragment for it, nor for anything seen
// through it, so it is drawn no further. Multisampled (samples > 1), the
// samples lie off the centres, so any rectangle that is not empty counts.
bool covers_pixel_centre(const NdcRect& rect, int width, int height, int samples = 1);

// The part of an eye's image where a portal's box can be visible from that
// eye, within `parent`; empty when the box is outside the frustum, faces
// away, or lies behind the eye. Conservative (never too small).
NdcRect portal_rect(const math::PortalRect& portal, const EyeView& eye);

// The part of an eye's image where a box (its eight corners in
// math::box_corners's order) may be seen, within the eye's rect. Conservative.
NdcRect box_rect(const math::dvec3 corners[8], const EyeView& eye);
// The same for the convex hull of `count` points (every pair's segment is
// clipped in front of the eye, so any hull will do; count <= 16).
NdcRect hull_rect(const math::dvec3* points, int count, const EyeView& eye);

}  // namespace impossible::render
