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

// The bound in the eye's image of the part in front of the eye (w >= eps)
// of the outline of `count` points (at most 16): the points there and the
// crossings of w = eps by its edges (`each_edge(f)` calls f(i, j) for each),
// within the eye's rect; none when all lie behind the eye. Edges that pass
// near the eye project far out and simply widen the bound (an eye inside a
// box gets the whole parent rect).
template <class EachEdge>
NdcRect bound_outline(const math::dvec3* points, int count, EachEdge each_edge, const EyeView& view) {
    math::dvec4 clip[16];
    for (int i = 0; i < count; ++i) clip[i] = view.view_proj * math::dvec4(points[i], 1.0);
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
    each_edge([&](int i, int j) {
        const math::dvec4& a = clip[i];
        const math::dvec4& b = clip[j];
        if ((a.w >= eps) != (b.w >= eps)) add(a + (b - a) * ((eps - a.w) / (b.w - a.w)));
    });
    if (!(x0 <= x1)) return NdcRect::none();  // wholly behind the eye
    return intersect(NdcRect{x0, y0, x1, y1}, view.rect);
}

// A box's edges, corners as math::box_corners orders them: the front
// rectangle's four first.
constexpr int kBoxEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                  {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

// The bound of the first `count` corners of a box (4: its front rectangle's
// outline; 8: the whole box).
NdcRect bound_corners(const math::dvec3 corners[8], int count, const EyeView& view) {
    const int edge_count = count == 8 ? 12 : 4;
    const auto each_edge = [edge_count](const auto& f) {
        for (int k = 0; k < edge_count; ++k) f(kBoxEdges[k][0], kBoxEdges[k][1]);
    };
    return bound_outline(corners, count, each_edge, view);
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
    // Every pair's segment: a superset of the hull's edges.
    const auto each_pair = [count](const auto& f) {
        for (int i = 0; i < count; ++i)
            for (int j = i + 1; j < count; ++j) f(i, j);
    };
    return bound_outline(points, count, each_pair, view);
}

NdcRect box_rect(const math::dvec3 corners[8], const EyeView& view) {
    if (!view.active || view.rect.empty()) return NdcRect::none();
    return bound_corners(corners, 8, view);
}

}  // namespace impossible::render
