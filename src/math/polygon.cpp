// Simple polygons on the floor plane; see polygon.hpp (Sutherland–Hodgman
// clipping, shoelace area, even–odd point test).
#include "math/polygon.hpp"

#include <algorithm>
#include <cmath>

namespace impossible::math {
namespace {

double cross(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }

// Sign of the turn a → b → c: > 0 left, < 0 right, 0 collinear.
double orient(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) { return cross(b - a, c - a); }

bool on_segment(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
    return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
           p.y <= std::max(a.y, b.y);
}

}  // namespace

double signed_area(const Polygon2& poly) {
    double sum = 0.0;
    for (std::size_t i = 0, n = poly.size(); i < n; ++i) sum += cross(poly[i], poly[(i + 1) % n]);
    return 0.5 * sum;
}

double area(const Polygon2& poly) { return std::abs(signed_area(poly)); }

Polygon2 rectangle(const glm::dvec2& min, const glm::dvec2& max) { return {min, {max.x, min.y}, max, {min.x, max.y}}; }

double distance_to_segment(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b) {
    const glm::dvec2 ab = b - a;
    const double len2 = ab.x * ab.x + ab.y * ab.y;
    const double t = len2 > 0.0 ? std::clamp(((p.x - a.x) * ab.x + (p.y - a.y) * ab.y) / len2, 0.0, 1.0) : 0.0;
    const glm::dvec2 q = a + ab * t;
    return std::hypot(p.x - q.x, p.y - q.y);
}

double distance_to_boundary(const Polygon2& poly, const glm::dvec2& p) {
    double best = INFINITY;
    for (std::size_t i = 0, n = poly.size(); i < n; ++i)
        best = std::min(best, distance_to_segment(p, poly[i], poly[(i + 1) % n]));
    return best;
}

bool contains(const Polygon2& poly, const glm::dvec2& p, double tolerance) {
    if (poly.size() < 3) return false;
    if (distance_to_boundary(poly, p) <= tolerance) return true;
    bool inside = false;  // even–odd crossings of a ray towards +x
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        const glm::dvec2 &a = poly[i], &b = poly[j];
        if ((a.y > p.y) != (b.y > p.y)) {
            const double x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
            if (p.x < x) inside = !inside;
        }
    }
    return inside;
}

bool segments_intersect(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, const glm::dvec2& d) {
    const double d1 = orient(c, d, a), d2 = orient(c, d, b), d3 = orient(a, b, c), d4 = orient(a, b, d);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
    return (d1 == 0 && on_segment(c, d, a)) || (d2 == 0 && on_segment(c, d, b)) || (d3 == 0 && on_segment(a, b, c)) ||
           (d4 == 0 && on_segment(a, b, d));
}

std::optional<PolygonProblem> simple_polygon_problem(const Polygon2& poly) {
    const int n = static_cast<int>(poly.size());
    if (n < 3) return PolygonProblem{0, "a polygon needs at least 3 corners (got " + std::to_string(n) + ")"};
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < i; ++j)
            if (poly[i] == poly[j])
                return PolygonProblem{i, "corner " + std::to_string(i) + " repeats corner " + std::to_string(j)};
    for (int i = 0; i < n; ++i) {
        const glm::dvec2 &a = poly[i], &b = poly[(i + 1) % n];
        for (int j = 0; j < i; ++j) {
            const glm::dvec2 &c = poly[j], &d = poly[(j + 1) % n];
            const bool adjacent = (j + 1) % n == i || (i + 1) % n == j;
            if (adjacent) {
                // Adjacent edges share one corner; they may not fold back on each other.
                const glm::dvec2 shared = (j + 1) % n == i ? a : b;
                const glm::dvec2 p = shared == a ? b : a, q = shared == c ? d : c;
                if (orient(shared, p, q) == 0 && (p - shared).x * (q - shared).x + (p - shared).y * (q - shared).y > 0)
                    return PolygonProblem{i, "edges " + std::to_string(j) + " and " + std::to_string(i) + " overlap"};
                continue;
            }
            if (segments_intersect(a, b, c, d))
                return PolygonProblem{i, "edge " + std::to_string(i) + " crosses edge " + std::to_string(j) +
                                             " (the polygon intersects itself)"};
        }
    }
    if (area(poly) <= 0.0) return PolygonProblem{0, "the polygon has no area"};
    return std::nullopt;
}

Polygon2 clip_to_convex(const Polygon2& subject, const Polygon2& convex) {
    Polygon2 out = subject;
    const double sign = signed_area(convex) >= 0.0 ? 1.0 : -1.0;
    for (std::size_t e = 0, m = convex.size(); e < m && !out.empty(); ++e) {
        const glm::dvec2 a = convex[e], b = convex[(e + 1) % m];
        auto inside = [&](const glm::dvec2& p) { return sign * orient(a, b, p) >= 0.0; };
        auto meet = [&](const glm::dvec2& p, const glm::dvec2& q) {
            const double dp = orient(a, b, p), dq = orient(a, b, q);
            return p + (q - p) * (dp / (dp - dq));
        };
        const Polygon2 in = std::move(out);
        out.clear();
        for (std::size_t i = 0, n = in.size(); i < n; ++i) {
            const glm::dvec2 p = in[i], q = in[(i + 1) % n];
            const bool pin = inside(p), qin = inside(q);
            if (pin) out.push_back(p);
            if (pin != qin) out.push_back(meet(p, q));
        }
    }
    return out;
}

double intersection_area(const Polygon2& poly, const Polygon2& convex) { return area(clip_to_convex(poly, convex)); }

bool convex_inside(const Polygon2& convex, const Polygon2& poly, double tolerance) {
    return area(convex) - intersection_area(poly, convex) <= tolerance;
}

bool segment_inside(const Polygon2& poly, const glm::dvec2& a, const glm::dvec2& b, double tolerance) {
    if (!contains(poly, a, tolerance) || !contains(poly, b, tolerance)) return false;
    // A segment with both ends inside leaves the polygon only where it properly
    // crosses an edge; test the midpoints between consecutive crossings.
    std::vector<double> ts{0.0, 1.0};
    for (std::size_t i = 0, n = poly.size(); i < n; ++i) {
        const glm::dvec2 c = poly[i], d = poly[(i + 1) % n];
        const double den = cross(b - a, d - c);
        if (den == 0.0) continue;
        const double t = cross(c - a, d - c) / den, u = cross(c - a, b - a) / den;
        if (t > 0.0 && t < 1.0 && u >= 0.0 && u <= 1.0) ts.push_back(t);
    }
    std::sort(ts.begin(), ts.end());
    for (std::size_t i = 0; i + 1 < ts.size(); ++i)
        if (!contains(poly, a + (b - a) * (0.5 * (ts[i] + ts[i + 1])), tolerance)) return false;
    return true;
}

}  // namespace impossible::math
