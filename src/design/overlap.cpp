// Room overlaps on the physical floor against Suma et al. 2012; see overlap.hpp.
#include "design/overlap.hpp"

#include <algorithm>

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
    std::vector<Overlap> out;
    for (std::size_t i = 0; i < floors.size(); ++i) {
        for (std::size_t j = i + 1; j < floors.size(); ++j) {
            Overlap o = overlap_of(floors[i], floors[j]);
            if (o.area <= kMinSharedArea) continue;
            o.a = static_cast<int>(i);
            o.b = static_cast<int>(j);
            out.push_back(std::move(o));
        }
    }
    return out;
}

}  // namespace impossible::design
