// Intersections of simple polygons by Boost.Geometry (design/overlap.hpp);
// the only file that includes it (docs/choices.md: heavy headers stay in one
// translation unit).
#include <algorithm>
#include <optional>

// Without rescaling: Boost 1.74 by default snaps intersection points to an
// integer grid over the pair's bounding box, which moves areas by about 1e-7
// m² (a 2 x 2 square and its 45° turn share 3.31370859 m², not 8(√2 - 1) =
// 3.31370850); from Boost 1.77 on, no rescaling is the default.
#define BOOST_GEOMETRY_NO_ROBUSTNESS
// Boost.Math, which Boost.Geometry includes, includes a header Boost 1.74
// itself marks deprecated; its note would print on every build.
#define BOOST_ALLOW_DEPRECATED_HEADERS
#include <boost/geometry/algorithms/area.hpp>
#include <boost/geometry/algorithms/correct.hpp>
#include <boost/geometry/algorithms/intersection.hpp>
#include <boost/geometry/core/exception.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>

#include "design/overlap.hpp"

namespace impossible::design {
namespace {

namespace bg = boost::geometry;
using BgPoint = bg::model::d2::point_xy<double>;
using BgPolygon = bg::model::polygon<BgPoint, /*ClockWise=*/false, /*Closed=*/true>;
using BgMulti = bg::model::multi_polygon<BgPolygon>;

BgPolygon to_boost(const math::Polygon2& poly) {
    BgPolygon out;
    for (const glm::dvec2& p : poly) out.outer().push_back(BgPoint(p.x, p.y));
    if (!poly.empty()) out.outer().push_back(BgPoint(poly.front().x, poly.front().y));
    bg::correct(out);  // counter-clockwise and closed, whichever winding came in
    return out;
}

double cross(const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Whether p lies in the closed counter-clockwise triangle abc.
bool in_triangle(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
    return cross(a, b, p) >= 0.0 && cross(b, c, p) >= 0.0 && cross(c, a, p) >= 0.0;
}

// A simple polygon cut into triangles by ear clipping (Meisters 1975, "Polygons
// have ears", Amer. Math. Monthly 82(6)). The search for the next ear goes
// on from the last one, so a polygon of n corners takes about n² steps
// (n³ at worst).
std::vector<math::Polygon2> triangles_of(math::Polygon2 poly) {
    if (math::signed_area(poly) < 0.0) std::reverse(poly.begin(), poly.end());
    std::vector<math::Polygon2> out;
    std::size_t from = 0;
    while (poly.size() > 3) {
        const std::size_t n = poly.size();
        std::size_t ear = n;
        for (std::size_t step = 0; step < n && ear == n; ++step) {
            const std::size_t i = (from + step) % n;
            const glm::dvec2 &a = poly[(i + n - 1) % n], &b = poly[i], &c = poly[(i + 1) % n];
            const double turn = cross(a, b, c);
            if (turn == 0.0) ear = i;  // a straight corner: dropped, it cuts off no area
            if (turn <= 0.0) continue;
            bool empty = true;
            for (std::size_t k = 0; k < n && empty; ++k)
                if (k != i && k != (i + 1) % n && k != (i + n - 1) % n) empty = !in_triangle(poly[k], a, b, c);
            if (empty) ear = i;
        }
        if (ear == n) ear = from % n;  // rounding hid every ear: cut one anyway rather than loop
        const glm::dvec2 &a = poly[(ear + n - 1) % n], &b = poly[ear], &c = poly[(ear + 1) % n];
        if (cross(a, b, c) > 0.0) out.push_back({a, b, c});
        poly.erase(poly.begin() + static_cast<std::ptrdiff_t>(ear));
        from = ear == 0 ? 0 : ear - 1;
    }
    if (poly.size() == 3 && math::signed_area(poly) > 0.0) out.push_back(poly);
    return out;
}

// Whether the edges of a and b meet (cross or touch) at more than `cap`
// pairs of edges; n·m segment tests at most, fewer where bounding boxes part.
bool meet_more_than(const math::Polygon2& a, const math::Polygon2& b, std::size_t cap) {
    glm::dvec2 lo = b[0], hi = b[0];
    for (const glm::dvec2& p : b) lo = glm::min(lo, p), hi = glm::max(hi, p);
    std::size_t meetings = 0;
    for (std::size_t i = 0, n = a.size(); i < n; ++i) {
        const glm::dvec2 p = a[i], q = a[(i + 1) % n];
        const glm::dvec2 elo = glm::min(p, q), ehi = glm::max(p, q);
        if (ehi.x < lo.x || ehi.y < lo.y || elo.x > hi.x || elo.y > hi.y) continue;
        for (std::size_t k = 0, m = b.size(); k < m; ++k) {
            const glm::dvec2 r = b[k], t = b[(k + 1) % m];
            if (std::max(r.x, t.x) < elo.x || std::max(r.y, t.y) < elo.y || std::min(r.x, t.x) > ehi.x ||
                std::min(r.y, t.y) > ehi.y)
                continue;
            if (math::segments_intersect(p, q, r, t) && ++meetings > cap) return true;
        }
    }
    return false;
}

// The library's pieces, or nothing when it should not be asked: its time
// grows with the square of the points where the boundaries meet
// (kMaxLibraryMeetings), or it refused the pair.
std::optional<BgMulti> library_intersection(const math::Polygon2& a, const math::Polygon2& b) {
    if (meet_more_than(a, b, kMaxLibraryMeetings)) return std::nullopt;
    BgMulti shared;
    try {
        bg::intersection(to_boost(a), to_boost(b), shared);
    } catch (const bg::exception&) {
        return std::nullopt;
    }
    return shared;
}

math::Polygon2 from_ring(const BgPolygon::ring_type& ring) {
    math::Polygon2 out;
    for (const BgPoint& p : ring) out.push_back({p.x(), p.y()});
    if (out.size() > 1 && out.front() == out.back()) out.pop_back();
    return out;
}

}  // namespace

double intersection_area_by_triangles(const math::Polygon2& a, const math::Polygon2& b) {
    if (a.size() < 3 || b.size() < 3) return 0.0;
    double sum = 0.0;
    for (const math::Polygon2& t : triangles_of(b)) sum += math::intersection_area(a, t);
    return sum;
}

std::vector<math::Polygon2> intersection(const math::Polygon2& a, const math::Polygon2& b) {
    std::vector<math::Polygon2> pieces;
    if (a.size() < 3 || b.size() < 3) return pieces;
    const std::optional<BgMulti> shared = library_intersection(a, b);
    if (!shared) {
        // The triangles' clips, each a piece (they share edges, not area).
        for (const math::Polygon2& t : triangles_of(b))
            if (math::Polygon2 piece = math::clip_to_convex(a, t); math::area(piece) > 0.0) {
                if (math::signed_area(piece) < 0.0) std::reverse(piece.begin(), piece.end());
                pieces.push_back(std::move(piece));
            }
        return pieces;
    }
    for (const BgPolygon& piece : *shared) {
        // Two simple polygons share pieces without holes: a hole would need
        // one of them to enclose a part of the other's outside.
        math::Polygon2 outer = from_ring(piece.outer());
        if (outer.size() >= 3 && math::area(outer) > 0.0) pieces.push_back(std::move(outer));
    }
    return pieces;
}

double intersection_area(const math::Polygon2& a, const math::Polygon2& b) {
    if (a.size() < 3 || b.size() < 3) return 0.0;
    const std::optional<BgMulti> shared = library_intersection(a, b);
    return shared ? bg::area(*shared) : intersection_area_by_triangles(a, b);
}

}  // namespace impossible::design
