// Room overlaps on the physical floor against Suma et al. 2012; see overlap.hpp.
#include "design/overlap.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>
#include <vector>

namespace impossible::design {

double overlap_limit_percent(double smaller_area) {
    return smaller_area <= kSmallRoomArea + 1e-9 ? kSmallRoomLimit : kLargeRoomLimit;
}

bool is_convex(const math::Polygon2& poly) {
    bool left = false, right = false;
    for (std::size_t i = 0, n = poly.size(); i < n; ++i) {
        const glm::dvec2 e0 = poly[(i + 1) % n] - poly[i], e1 = poly[(i + 2) % n] - poly[(i + 1) % n];
        const double turn = e0.x * e1.y - e0.y * e1.x;
        left = left || turn > 0.0;
        right = right || turn < 0.0;
    }
    return !(left && right);
}

bool polygon_inside(const math::Polygon2& inner, const math::Polygon2& outer, double tolerance) {
    if (is_convex(inner)) return math::convex_inside(inner, outer, tolerance);
    return math::area(inner) - intersection_area(outer, inner) <= tolerance;
}

Overlap overlap_of(const math::Polygon2& a, const math::Polygon2& b) {
    Overlap o;
    if (is_convex(a) && is_convex(b)) {
        math::Polygon2 shared = math::clip_to_convex(a, b);
        o.area = math::area(shared);
        if (!shared.empty()) o.shared.push_back(std::move(shared));
    } else {
        o.shared = intersection(a, b);
        for (const math::Polygon2& piece : o.shared) o.area += math::area(piece);
    }
    const double smaller = std::min(math::area(a), math::area(b));
    o.percent = smaller > 0.0 ? 100.0 * o.area / smaller : 0.0;
    o.limit = overlap_limit_percent(smaller);
    o.noticeable = o.area > kMinSharedArea && o.percent > o.limit + 1e-9;
    return o;
}

namespace {

struct FloorBounds {
    glm::dvec2 lo{-INFINITY}, hi{INFINITY};
    double magnitude = INFINITY;  // the largest |coordinate|
    bool rectangle = false;       // an axis-aligned rectangle: the floor is its bounds
};

// A floor with a coordinate that is not finite meets every other, as a plain
// test of every pair would have it.
FloorBounds bounds_of(const math::Polygon2& f) {
    FloorBounds b;
    const bool finite =
        std::all_of(f.begin(), f.end(), [](const glm::dvec2& p) { return std::isfinite(p.x) && std::isfinite(p.y); });
    if (!finite || f.empty()) return b;
    b.lo = b.hi = f[0];
    for (const glm::dvec2& p : f) b.lo = glm::min(b.lo, p), b.hi = glm::max(b.hi, p);
    b.magnitude = std::max({-b.lo.x, -b.lo.y, b.hi.x, b.hi.y});
    if (f.size() == 4) {
        // Edges alternately along x and along y, none of zero length.
        bool along[2] = {true, true};  // [0]: edges 0 and 2 along x, 1 and 3 along y; [1]: the other way
        for (std::size_t i = 0; i < 4; ++i) {
            const glm::dvec2 p = f[i], q = f[(i + 1) % 4];
            const bool x = p.y == q.y && p.x != q.x, y = p.x == q.x && p.y != q.y;
            along[0] = along[0] && (i % 2 == 0 ? x : y);
            along[1] = along[1] && (i % 2 == 0 ? y : x);
        }
        b.rectangle = along[0] || along[1];
    }
    return b;
}

// The sweep's state: the listed pairs as a heap (the largest (a, b) on top).
class OverlapSweep {
public:
    OverlapSweep(const std::vector<math::Polygon2>& floors, const OverlapLimits& limits)
        : floors_(floors), limits_(limits) {
        for (const math::Polygon2& f : floors) bounds_.push_back(bounds_of(f));
    }

    Overlaps run() {
        std::vector<std::size_t> by_x(floors_.size());
        std::iota(by_x.begin(), by_x.end(), std::size_t{0});
        std::sort(by_x.begin(), by_x.end(), [&](std::size_t a, std::size_t b) {
            return bounds_[a].lo.x < bounds_[b].lo.x || (bounds_[a].lo.x == bounds_[b].lo.x && a < b);
        });
        std::size_t candidates = 0;
        for (std::size_t s = 0; s < by_x.size() && out_.exact; ++s) {
            const FloorBounds& u = bounds_[by_x[s]];
            for (std::size_t t = s + 1; t < by_x.size() && bounds_[by_x[t]].lo.x <= u.hi.x; ++t) {
                if (++candidates > limits_.candidates) {
                    out_.exact = false;
                    break;
                }
                const FloorBounds& v = bounds_[by_x[t]];
                if (v.lo.y > u.hi.y || u.lo.y > v.hi.y) continue;
                if (!test(std::min(by_x[s], by_x[t]), std::max(by_x[s], by_x[t]))) break;
            }
        }
        std::sort_heap(out_.listed.begin(), out_.listed.end(), by_rooms);
        for (Overlap& o : out_.listed) {
            if (o.area >= 0.0) continue;  // a rectangle pair, clipped only now it is listed
            const int a = o.a, b = o.b;
            o = overlap_of(floors_[a], floors_[b]);
            o.a = a, o.b = b;
        }
        return std::move(out_);
    }

private:
    const std::vector<math::Polygon2>& floors_;
    OverlapLimits limits_;
    std::vector<FloorBounds> bounds_;
    std::size_t clipped_ = 0;
    std::size_t work_ = 0;  // corners multiplied, summed over the clipped pairs
    Overlaps out_;

    static bool by_rooms(const Overlap& x, const Overlap& y) { return x.a < y.a || (x.a == y.a && x.b < y.b); }

    // Whether the pair (i, j), i < j, may still be listed.
    bool listable(std::size_t i, std::size_t j) const {
        if (out_.listed.size() < limits_.listed) return true;
        if (out_.listed.empty()) return false;
        const Overlap& top = out_.listed.front();
        return static_cast<int>(i) < top.a || (static_cast<int>(i) == top.a && static_cast<int>(j) < top.b);
    }

    void add(std::size_t i, std::size_t j, Overlap o) {
        ++out_.pairs;
        if (!listable(i, j)) return;
        o.a = static_cast<int>(i), o.b = static_cast<int>(j);
        if (out_.listed.size() >= limits_.listed) {
            std::pop_heap(out_.listed.begin(), out_.listed.end(), by_rooms);
            out_.listed.pop_back();
        }
        out_.listed.push_back(std::move(o));
        std::push_heap(out_.listed.begin(), out_.listed.end(), by_rooms);
    }

    // The shared area of two rectangles, as clipping would find it, or a
    // negative number when rounding might put it on either side of
    // kMinSharedArea. Clipping and this product each err by a few units in
    // the last place of the squared coordinates; the margin is 100 times that.
    double rectangle_share(const FloorBounds& u, const FloorBounds& v) const {
        const double w = std::min(u.hi.x, v.hi.x) - std::max(u.lo.x, v.lo.x);
        const double h = std::min(u.hi.y, v.hi.y) - std::max(u.lo.y, v.lo.y);
        const double shared = w > 0.0 && h > 0.0 ? w * h : 0.0;
        const double m = std::max(u.magnitude, v.magnitude), margin = 1e-13 * (1.0 + m * m);
        return std::abs(shared - kMinSharedArea) > margin ? shared : -1.0;
    }

    // Tests the pair (i, j), i < j; false when the search must stop.
    bool test(std::size_t i, std::size_t j) {
        const FloorBounds &u = bounds_[i], &v = bounds_[j];
        const double shared = u.rectangle && v.rectangle ? rectangle_share(u, v) : -1.0;
        if (shared >= 0.0) {
            Overlap later;
            later.area = -1.0;
            if (shared > kMinSharedArea) add(i, j, std::move(later));
            return true;
        }
        work_ += floors_[i].size() * floors_[j].size();
        if (++clipped_ > limits_.clipped || work_ > limits_.work) {
            out_.exact = false;
            return false;
        }
        Overlap o = overlap_of(floors_[i], floors_[j]);
        if (o.area > kMinSharedArea) add(i, j, std::move(o));
        return true;
    }
};

}  // namespace

Overlaps room_overlaps(const std::vector<math::Polygon2>& floors, const OverlapLimits& limits) {
    return OverlapSweep(floors, limits).run();
}

}  // namespace impossible::design
