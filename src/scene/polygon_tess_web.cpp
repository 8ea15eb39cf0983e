// The web build's tessellator (there is no GLU in emscripten): ear clipping,
// with each hole joined to the outline by a bridge to a corner it sees.
// Same contract as polygon_tess.cpp (polygon_tess.hpp), but it adds no
// points: it handles holes that lie inside the outline without touching it
// or each other (what the loader accepts for prism rooms' walls; a polygon
// outside that gives an empty result, which the web build reports).
#include <algorithm>
#include <cmath>

#include "math/polygon.hpp"
#include "scene/polygon_tess.hpp"

namespace impossible::scene {
namespace {

using glm::dvec2;

double cross(dvec2 a, dvec2 b, dvec2 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

bool segments_cross(dvec2 a, dvec2 b, dvec2 c, dvec2 d) {
    const double d1 = cross(a, b, c), d2 = cross(a, b, d), d3 = cross(c, d, a), d4 = cross(c, d, b);
    return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0;
}

bool inside_triangle(dvec2 p, dvec2 a, dvec2 b, dvec2 c) {
    return cross(a, b, p) >= 0 && cross(b, c, p) >= 0 && cross(c, a, p) >= 0;
}

// The contours' points into out.points, as loops of indices: the outline
// counter-clockwise, the holes clockwise.
std::vector<std::vector<int>> loops_of(const std::vector<std::vector<dvec2>>& contours, Tessellation& out) {
    std::vector<std::vector<int>> loops;
    for (std::size_t c = 0; c < contours.size(); ++c) {
        std::vector<int> loop;
        for (const dvec2& p : contours[c]) {
            loop.push_back(static_cast<int>(out.points.size()));
            out.points.push_back(p);
        }
        if ((math::signed_area(contours[c]) > 0.0) != (c == 0)) std::reverse(loop.begin(), loop.end());
        loops.push_back(loop);
    }
    return loops;
}

// Joins each hole to the outline, rightmost hole first, by a bridge from its
// rightmost corner to the nearest corner it reaches without crossing an
// edge; false when some hole has no such corner.
bool bridge_holes(const std::vector<std::vector<int>>& loops, const std::vector<dvec2>& points,
                  std::vector<int>& poly) {
    const auto P = [&](int i) { return points[static_cast<std::size_t>(i)]; };
    std::vector<std::size_t> holes;
    for (std::size_t h = 1; h < loops.size(); ++h) holes.push_back(h);
    const auto max_x = [&](std::size_t h) {
        double m = -INFINITY;
        for (int i : loops[h]) m = std::max(m, P(i).x);
        return m;
    };
    std::sort(holes.begin(), holes.end(), [&](std::size_t a, std::size_t b) { return max_x(a) > max_x(b); });
    for (const std::size_t h : holes) {
        const std::vector<int>& hole = loops[h];
        std::size_t k = 0;
        for (std::size_t i = 1; i < hole.size(); ++i)
            if (P(hole[i]).x > P(hole[k]).x) k = i;
        const dvec2 m = P(hole[k]);
        int best = -1;
        double best_d = INFINITY;
        for (std::size_t j = 0; j < poly.size(); ++j) {
            const dvec2 v = P(poly[j]);
            const double d = glm::dot(v - m, v - m);
            if (d >= best_d) continue;
            bool blocked = false;
            for (std::size_t e = 0; e < poly.size() && !blocked; ++e)
                blocked = segments_cross(m, v, P(poly[e]), P(poly[(e + 1) % poly.size()]));
            for (std::size_t e = 0; e < hole.size() && !blocked; ++e)
                blocked = segments_cross(m, v, P(hole[e]), P(hole[(e + 1) % hole.size()]));
            if (!blocked) {
                best = static_cast<int>(j);
                best_d = d;
            }
        }
        if (best < 0) return false;
        std::vector<int> joined(poly.begin(), poly.begin() + best + 1);
        for (std::size_t i = 0; i <= hole.size(); ++i) joined.push_back(hole[(k + i) % hole.size()]);
        joined.insert(joined.end(), poly.begin() + best, poly.end());
        poly = joined;
    }
    return true;
}

// Clips one ear of `poly` into `triangles`, or drops a corner between
// collinear neighbours; false when neither is left.
bool clip_one(std::vector<int>& poly, const std::vector<dvec2>& points, std::vector<std::array<int, 3>>& triangles) {
    const auto P = [&](int i) { return points[static_cast<std::size_t>(i)]; };
    const std::size_t n = poly.size();
    for (std::size_t i = 0; i < n; ++i) {
        const int a = poly[(i + n - 1) % n], b = poly[i], c = poly[(i + 1) % n];
        if (cross(P(a), P(b), P(c)) <= 0) continue;
        bool empty = true;
        for (std::size_t j = 0; j < n && empty; ++j) {
            const int q = poly[j];
            if (q == a || q == b || q == c || P(q) == P(a) || P(q) == P(b) || P(q) == P(c)) continue;
            empty = !inside_triangle(P(q), P(a), P(b), P(c));
        }
        if (!empty) continue;
        triangles.push_back({a, b, c});
        poly.erase(poly.begin() + static_cast<std::ptrdiff_t>(i));
        return true;
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (cross(P(poly[(i + n - 1) % n]), P(poly[i]), P(poly[(i + 1) % n])) == 0) {
            poly.erase(poly.begin() + static_cast<std::ptrdiff_t>(i));
            return true;
        }
    }
    return false;
}

}  // namespace

Tessellation tessellate(const std::vector<std::vector<dvec2>>& contours) {
    Tessellation out;
    const std::vector<std::vector<int>> loops = loops_of(contours, out);
    if (loops.empty()) return out;
    std::vector<int> poly = loops[0];
    if (!bridge_holes(loops, out.points, poly)) return {};
    while (poly.size() > 3)
        if (!clip_one(poly, out.points, out.triangles)) return {};
    const auto P = [&](int i) { return out.points[static_cast<std::size_t>(i)]; };
    if (poly.size() == 3 && cross(P(poly[0]), P(poly[1]), P(poly[2])) > 0)
        out.triangles.push_back({poly[0], poly[1], poly[2]});
    return out;
}

}  // namespace impossible::scene
