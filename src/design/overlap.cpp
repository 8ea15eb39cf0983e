// Room overlaps on the physical floor against Suma et al. 2012; see overlap.hpp.
#include "design/overlap.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace impossible::design {

double overlap_limit_percent(double smaller_area) {
    return smaller_area <= kSmallRoomArea + 1e-9 ? kSmallRoomLimit : kLargeRoomLimit;
}

Overlap overlap_of(const math::Polygon2& a, const math::Polygon2& b) {
    Overlap o;
    o.shared = math::clip_to_convex(a, b);
    o.area = math::area(o.shared);
    const double smaller = std::min(math::area(a), math::area(b));
    o.percent = smaller > 0.0 ? 100.0 * o.area / smaller : 0.0;
    o.limit = overlap_limit_percent(smaller);
    o.noticeable = o.area > kMinSharedArea && o.percent > o.limit + 1e-9;
    return o;
}

std::vector<Overlap> room_overlaps(const std::vector<math::Polygon2>& floors) {
    // Only floors whose bounding rectangles meet can share any area: sort the
    // rectangles by their low x and sweep, so that a layout of n rooms that
    // mostly lie apart costs n log n plus the pairs that do meet, not n².
    // A floor with a coordinate that is not finite meets every other, as a
    // plain test of every pair would have it.
    struct Bounds {
        glm::dvec2 lo{-INFINITY}, hi{INFINITY};
    };
    std::vector<Bounds> bounds(floors.size());
    for (std::size_t i = 0; i < floors.size(); ++i) {
        const math::Polygon2& f = floors[i];
        const bool finite = std::all_of(f.begin(), f.end(),
                                        [](const glm::dvec2& p) { return std::isfinite(p.x) && std::isfinite(p.y); });
        if (!finite || f.empty()) continue;
        bounds[i].lo = bounds[i].hi = f[0];
        for (const glm::dvec2& p : f)
            bounds[i].lo = glm::min(bounds[i].lo, p), bounds[i].hi = glm::max(bounds[i].hi, p);
    }
    std::vector<std::size_t> by_x(floors.size());
    std::iota(by_x.begin(), by_x.end(), std::size_t{0});
    std::sort(by_x.begin(), by_x.end(), [&](std::size_t a, std::size_t b) {
        return bounds[a].lo.x < bounds[b].lo.x || (bounds[a].lo.x == bounds[b].lo.x && a < b);
    });
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    for (std::size_t s = 0; s < by_x.size(); ++s) {
        const Bounds& u = bounds[by_x[s]];
        for (std::size_t t = s + 1; t < by_x.size() && bounds[by_x[t]].lo.x <= u.hi.x; ++t) {
            const Bounds& v = bounds[by_x[t]];
            if (v.lo.y > u.hi.y || u.lo.y > v.hi.y) continue;
            pairs.emplace_back(std::min(by_x[s], by_x[t]), std::max(by_x[s], by_x[t]));
        }
    }
    std::sort(pairs.begin(), pairs.end());

    std::vector<Overlap> out;
    for (const auto& [i, j] : pairs) {
        Overlap o = overlap_of(floors[i], floors[j]);
        if (o.area <= kMinSharedArea) continue;
        o.a = static_cast<int>(i);
        o.b = static_cast<int>(j);
        out.push_back(std::move(o));
    }
    return out;
}

}  // namespace impossible::design
