#include "preview/grid.hpp"

#include <algorithm>
#include <cmath>

#include "math/polygon.hpp"
#include "preview/head.hpp"

namespace impossible::preview {

float grid_alpha(double d) { return static_cast<float>(std::clamp(1.0 - d / kGridDistance, 0.0, 1.0)); }

namespace {

// A polygonal play area: a grid on every edge the head is near.
int add_polygon_grid(OverlayBatch& batch, const std::vector<glm::dvec2>& poly, const math::dvec3& head,
                     const math::dmat4& vp) {
    auto clip = [&](const math::dvec3& p) { return glm::vec4(vp * math::dvec4(p, 1.0)); };
    const double top = std::max(kGridHeight, head.y + 0.5);
    const bool inside = math::contains(poly, {head.x, head.z});
    int walls = 0;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const glm::dvec2 a = poly[i], b = poly[(i + 1) % poly.size()];
        const double d = math::distance_to_segment({head.x, head.z}, a, b);
        const float alpha = grid_alpha(inside ? d : -d);
        if (alpha <= 0.0f) continue;
        ++walls;
        const glm::vec4 color{0.25f, 0.85f, 1.0f, 0.25f + 0.75f * alpha};
        const double length = glm::distance(a, b);
        const int columns = static_cast<int>(std::floor(length / kGridSpacing + 1e-9));
        for (int k = 0; k <= columns + 1; ++k) {
            const glm::dvec2 p = a + (b - a) * (std::min(k * kGridSpacing, length) / length);
            batch.clip_line(clip({p.x, 0.0, p.y}), clip({p.x, top, p.y}), color);
            if (k * kGridSpacing >= length) break;
        }
        const int rows = static_cast<int>(std::floor(top / kGridSpacing + 1e-9));
        for (int j = 0; j <= rows; ++j)
            batch.clip_line(clip({a.x, j * kGridSpacing, a.y}), clip({b.x, j * kGridSpacing, b.y}), color);
    }
    return walls;
}

}  // namespace

int add_boundary_grid(OverlayBatch& batch, const layout::PlayArea& area, const math::dvec3& head, const math::Eye& eye,
                      const math::dmat4& projection) {
    if (!area.polygon.empty()) return add_polygon_grid(batch, area.polygon, head, projection * math::view_matrix(eye));
    const std::optional<std::array<double, 4>> d = edge_distances(head, area);
    const math::dmat4 vp = projection * math::view_matrix(eye);
    auto clip = [&](const math::dvec3& p) { return glm::vec4(vp * math::dvec4(p, 1.0)); };
    const double top = std::max(kGridHeight, head.y + 0.5);
    int walls = 0;
    for (int w = 0; w < 4; ++w) {
        const float alpha = grid_alpha((*d)[w]);
        if (alpha <= 0.0f) continue;
        ++walls;
        const glm::vec4 color{0.25f, 0.85f, 1.0f, 0.25f + 0.75f * alpha};
        // The wall runs along x (walls 2, 3 at z = const) or along z (0, 1 at x = const).
        const bool along_x = w >= 2;
        const double fixed = w == 0 ? area.min.x : w == 1 ? area.max.x : w == 2 ? area.min.y : area.max.y;
        const double lo = along_x ? area.min.x : area.min.y, hi = along_x ? area.max.x : area.max.y;
        auto point = [&](double s, double y) { return along_x ? math::dvec3{s, y, fixed} : math::dvec3{fixed, y, s}; };
        const int columns = static_cast<int>(std::floor((hi - lo) / kGridSpacing + 1e-9));
        for (int i = 0; i <= columns + 1; ++i) {
            const double s = std::min(lo + i * kGridSpacing, hi);
            batch.clip_line(clip(point(s, 0.0)), clip(point(s, top)), color);
            if (s >= hi) break;
        }
        const int rows = static_cast<int>(std::floor(top / kGridSpacing + 1e-9));
        for (int j = 0; j <= rows; ++j)
            batch.clip_line(clip(point(lo, j * kGridSpacing)), clip(point(hi, j * kGridSpacing)), color);
    }
    return walls;
}

}  // namespace impossible::preview
