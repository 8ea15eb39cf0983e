// The truncated pyramid a light image's path may light (lit_region.hpp).
#include "lights/lit_region.hpp"

#include <algorithm>
#include <cmath>

#include <glm/matrix.hpp>

#include "math/portal.hpp"

namespace impossible::lights {

LitRegion lit_region(const LightImage& image, const glm::dvec3& room_min, const glm::dvec3& room_max) {
    LitRegion out;
    if (image.apertures.empty()) return out;
    const math::PortalRect& p1 = image.apertures.front().rect;
    // L' must lie behind P1 (the surface is on its normal's side).
    const double h = glm::dot(p1.normal, p1.center - image.position);
    if (h < -kMinApertureDistance) out.kind = LitRegion::Kind::Nowhere;
    if (!(h > kMinApertureDistance)) return out;
    // The pyramid's point at ray parameter s (L' + s (q - L'), q on P1) lies
    // at a distance of at least s · h from L'; every point of the room, with
    // a margin for hands and objects reaching past its walls, is nearer than
    // `reach`, so s = reach / h bounds the part that matters.
    const double s = light_reach(image.position, room_min, room_max) / h;
    math::dvec3 box[8];
    math::box_corners(p1, box);  // 0..3: the front rectangle, at depth 0
    out.kind = LitRegion::Kind::Pyramid;
    for (int k = 0; k < 4; ++k) {
        out.corners[static_cast<size_t>(k)] = box[k];
        out.corners[static_cast<size_t>(k) + 4] = image.position + s * (box[k] - image.position);
    }
    return out;
}

double light_reach(const glm::dvec3& light, const glm::dvec3& room_min, const glm::dvec3& room_max) {
    double reach = 0.0;
    for (int k = 0; k < 8; ++k) {
        const glm::dvec3 corner((k & 1) ? room_max.x : room_min.x, (k & 2) ? room_max.y : room_min.y,
                                (k & 4) ? room_max.z : room_min.z);
        reach = std::max(reach, glm::length(corner - light));
    }
    return reach + glm::length(room_max - room_min) + 10.0;
}

bool shadow_region(const glm::dvec3& light, const glm::dmat4& from_box, glm::dvec3 lo, glm::dvec3 hi, double reach,
                   double grow_angle, std::array<glm::dvec3, 16>& corners_out) {
    const glm::dvec3 l = glm::dvec3(glm::inverse(from_box) * glm::dvec4(light, 1.0));
    const double grow = glm::length(glm::max(glm::abs(lo - l), glm::abs(hi - l))) * grow_angle + 1e-4;
    lo -= grow;
    hi += grow;
    const double dmin = glm::length(glm::max(glm::max(lo - l, l - hi), glm::dvec3(0.0)));
    if (!(dmin > kMinApertureDistance)) return false;
    // A point L' + t (q - L') with q in the box lies at least t · dmin from
    // L': within `reach` only for t <= reach / dmin.
    const double t = std::max(1.0, reach / dmin);
    for (int k = 0; k < 8; ++k) {
        const glm::dvec3 own((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z);
        const glm::dvec3 q = glm::dvec3(from_box * glm::dvec4(own, 1.0));
        corners_out[static_cast<size_t>(k)] = q;
        corners_out[static_cast<size_t>(k) + 8] = light + t * (q - light);
    }
    return true;
}

}  // namespace impossible::lights
