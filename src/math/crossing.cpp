// The swept segment-versus-portal test (see crossing.hpp).
#include "math/crossing.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace impossible::math {

bool within_rectangle(const PortalRect& p, const dvec3& point) {
    const dvec3 v = point - p.center;
    return std::abs(glm::dot(v, portal_right(p))) <= 0.5 * p.width && std::abs(glm::dot(v, p.up)) <= 0.5 * p.height;
}

std::optional<SegmentCrossing> segment_crossing(const PortalRect& p, const dvec3& p0, const dvec3& p1) {
    const double d0 = signed_distance(p, p0);
    const double d1 = signed_distance(p, p1);
    if (!(d0 >= 0.0 && d1 < 0.0)) return std::nullopt;  // also rejects NaN
    // d0 ≥ 0 > d1, so d0 - d1 > 0 and 0 ≤ t ≤ 1 (≤ 1 after rounding too;
    // the clamp only guards against overflow of d0 - d1).
    const double t = std::clamp(d0 / (d0 - d1), 0.0, 1.0);
    const dvec3 point = t == 1.0 ? p1 : p0 + t * (p1 - p0);
    if (!within_rectangle(p, point)) return std::nullopt;
    return SegmentCrossing{t, point};
}

bool has_inner_faces(const PortalRect& p, const dvec3& eye, const dvec3& head) {
    if (!in_column(p, eye)) return false;
    return signed_distance(p, eye) >= 0.0 || segment_crossing(p, head, eye).has_value();
}

}  // namespace impossible::math
