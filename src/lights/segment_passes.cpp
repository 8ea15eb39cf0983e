// The exact aperture test of a light image (see light_images.hpp).
#include <cmath>

#include <glm/geometric.hpp>

#include "lights/light_images.hpp"
#include "shading/lighting.hpp"

namespace impossible::lights {

namespace {

// Where the segment p + t·(q - p), 0 < t < 1, crosses the rectangle's plane
// from its front to its back; -1 when it does not.
double sp_crossing(const math::PortalRect& rect, const glm::dvec3& p, const glm::dvec3& q) {
    const double dp = math::signed_distance(rect, p);
    const double dq = math::signed_distance(rect, q);
    if (!(dp > 0.0 && dq < 0.0)) return -1.0;
    return dp / (dp - dq);
}

// The point's offsets from the centre along right and up, against the half sizes.
bool sp_inside(const math::PortalRect& rect, const glm::dvec3& x, bool strict) {
    const glm::dvec3 v = x - rect.center;
    const double a = std::abs(glm::dot(v, math::portal_right(rect))) - 0.5 * rect.width;
    const double b = std::abs(glm::dot(v, rect.up)) - 0.5 * rect.height;
    return strict ? (a < 0.0 && b < 0.0) : (a <= 0.0 && b <= 0.0);
}

}  // namespace

bool segment_passes(const LightImage& image, const glm::dvec3& p) {
    const glm::dvec3 q = image.position;
    const glm::dvec3 dir = q - p;
    const std::size_t k = image.apertures.size();
    std::vector<double> t(k + 2, 0.0);
    t[k + 1] = 1.0;
    for (std::size_t i = 0; i < k; ++i) {
        const math::PortalRect& rect = image.apertures[i].rect;
        const double ti = sp_crossing(rect, p, q);
        if (ti < 0.0 || !(ti > t[i]) || !sp_inside(rect, p + dir * ti, true)) return false;
        t[i + 1] = ti;
    }
    const double start = shading::shadow_ray_start_tolerance(p) / glm::length(dir);
    for (const Blocker& blocker : image.blockers) {
        const std::size_t leg = static_cast<std::size_t>(blocker.leg);
        if (leg > k) continue;
        const double tb = sp_crossing(blocker.rect, p, q);
        if (tb < 0.0 || tb <= t[leg] || tb >= t[leg + 1]) continue;
        if (leg == 0 && tb <= start) continue;
        if (sp_inside(blocker.rect, p + dir * tb, false)) return false;
    }
    return true;
}

}  // namespace impossible::lights
