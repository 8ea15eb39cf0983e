// Per-eye screen bounds of a portal box, for culling and for narrowing the
// next level's view (the scissor rectangle and the clip-distance rectangle).
#include <algorithm>
#include <cmath>

#include "math/crossing.hpp"
#include "render/portals/view.hpp"

namespace impossible::render {

namespace {

// Whether [lo, hi] (NDC) holds a pixel centre (2i + 1)/n - 1, i in 0..n-1.
bool spans_centre(double lo, double hi, int n) {
    const double margin = 2.0 / n / 256.0;
    const double first = std::ceil(((lo - margin + 1.0) * n - 1.0) / 2.0);  // lowest i at or above lo
    const double i = std::max(first, 0.0);
    return i <= n - 1 && (2.0 * i + 1.0) / n - 1.0 <= hi + margin;
}

}  // namespace

bool covers_pixel_centre(const NdcRect& rect, int width, int height, int samples) {
    if (rect.empty()) return false;
    return samples > 1 || (spans_centre(rect.x0, rect.x1, width) && spans_centre(rect.y0, rect.y1, height));
}

namespace {

// The bound in the eye's image of the first `count` corners of a box (4: its
// front rectangle's outline; 8: the whole box, corners as math::box_corners
// orders them), within the eye's rect; none when all lie behind the eye.
NdcRect bound_corners(const math::dvec3 corners[8], int count, const EyeView& view) {
    math::dvec4 clip[8];
    for (int i = 0; i < count; ++i) clip[i] = view.view_proj * math::dvec4(corners[i], 1.0);

    // Clip the outline's edges at w = eps (just in front of the eye) and bound
    // what remains; edges that pass near the eye project far out and simply
    // widen the bound (an eye inside the box gets the whole parent rect).
    static constexpr int kEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                          {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    const int edge_count = count == 8 ? 12 : 4;
    const double eps = 1e-9;
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    auto add = [&](const math::dvec4& c) {
        const double x = c.x / c.w, y = c.y / c.w;
        x0 = std::min(x0, x);
        x1 = std::max(x1, x);
        y0 = std::min(y0, y);
        y1 = std::max(y1, y);
    };
    for (int i = 0; i < count; ++i)
        if (clip[i].w >= eps) add(clip[i]);
    for (int k = 0; k < edge_count; ++k) {
        const math::dvec4& a = clip[kEdges[k][0]];
        const math::dvec4& b = clip[kEdges[k][1]];
        if ((a.w >= eps) != (b.w >= eps)) add(a + (b - a) * ((eps - a.w) / (b.w - a.w)));
    }
    if (!(x0 <= x1)) return NdcRect::none();  // wholly behind the eye
    return intersect(NdcRect{x0, y0, x1, y1}, view.rect);
}

}  // namespace

NdcRect portal_rect(const math::PortalRect& portal, const EyeView& view) {
    if (!view.active || view.rect.empty()) return NdcRect::none();
    // An eye with the inner faces (in the box's column, reached through the
    // door) may see all eight corners; any other eye sees only the front
    // face, and only from in front.
    const bool inner = math::has_inner_faces(portal, view.eye.position, view.eye.head);
    if (!inner && math::signed_distance(portal, view.eye.position) <= 0.0) return NdcRect::none();
    math::dvec3 corners[8];
    math::box_corners(portal, corners);
    return bound_corners(corners, inner ? 8 : 4, view);
}

NdcRect hull_rect(const math::dvec3* points, int count, const EyeView& view) {
    if (!view.active || view.rect.empty() || count <= 0 || count > 16) return count > 16 ? view.rect : NdcRect::none();
    math::dvec4 clip[16];
    for (int i = 0; i < count; ++i) clip[i] = view.view_proj * math::dvec4(points[i], 1.0);
    // The hull's part in front of the eye (w >= eps) is the hull of its
    // points there and of the crossings of w = eps by segments between its
    // points: every pair's, a superset of its edges'.
    const double eps = 1e-9;
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    auto add = [&](const math::dvec4& c) {
        x0 = std::min(x0, c.x / c.w);
        x1 = std::max(x1, c.x / c.w);
        y0 = std::min(y0, c.y / c.w);
        y1 = std::max(y1, c.y / c.w);
    };
    for (int i = 0; i < count; ++i) {
        if (clip[i].w >= eps) add(clip[i]);
        for (int k = i + 1; k < count; ++k)
            if ((clip[i].w >= eps) != (clip[k].w >= eps))
                add(clip[i] + (clip[k] - clip[i]) * ((eps - clip[i].w) / (clip[k].w - clip[i].w)));
    }
    if (!(x0 <= x1)) return NdcRect::none();
    return intersect(NdcRect{x0, y0, x1, y1}, view.rect);
}

NdcRect box_rect(const math::dvec3 corners[8], const EyeView& view) {
    if (!view.active || view.rect.empty()) return NdcRect::none();
    return bound_corners(corners, 8, view);
}

}  // namespace impossible::render
