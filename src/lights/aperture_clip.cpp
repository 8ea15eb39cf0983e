// Convex polygons in space (see aperture_clip.hpp).
#include "lights/aperture_clip.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

namespace impossible::lights {

using math::dvec3;

Polygon3 rect_polygon(const math::PortalRect& rect, double eps) {
    const dvec3 r = math::portal_right(rect) * (0.5 * rect.width + eps);
    const dvec3 u = rect.up * (0.5 * rect.height + eps);
    return {rect.center - r - u, rect.center + r - u, rect.center + r + u, rect.center - r + u};
}

Polygon3 clip_half_space(const Polygon3& poly, const dvec3& normal, double offset, double eps) {
    Polygon3 out;
    const std::size_t n = poly.size();
    out.reserve(n + 1);
    for (std::size_t i = 0; i < n; ++i) {
        const dvec3& a = poly[i];
        const dvec3& b = poly[(i + 1) % n];
        const double da = glm::dot(normal, a) + offset + eps;
        const double db = glm::dot(normal, b) + offset + eps;
        if (da >= 0.0) out.push_back(a);
        if ((da >= 0.0) != (db >= 0.0)) {
            const double t = da / (da - db);
            out.push_back(a + (b - a) * t);
        }
    }
    return out;
}

namespace {

dvec3 aperture_clip_centroid(const Polygon3& poly) {
    dvec3 sum(0.0);
    for (const dvec3& p : poly) sum += p;
    return sum / static_cast<double>(poly.size());
}

}  // namespace

Polygon3 clip_to_cone(const Polygon3& poly, const dvec3& apex, const Polygon3& window, double eps) {
    if (window.size() < 2) return poly;
    const dvec3 inside = aperture_clip_centroid(window) - apex;
    Polygon3 out = poly;
    const std::size_t n = window.size();
    for (std::size_t i = 0; i < n && !out.empty(); ++i) {
        const dvec3 a = window[i] - apex;
        const dvec3 b = window[(i + 1) % n] - apex;
        dvec3 normal = glm::cross(a, b);
        const double len = glm::length(normal);
        if (!(len > 1e-300)) continue;
        normal /= len;
        const double side = glm::dot(normal, inside);
        // A window seen edge-on from the apex (or one edge of a sliver):
        // the side is not known, so this plane does not clip.
        if (std::abs(side) <= eps) continue;
        if (side < 0.0) normal = -normal;
        out = clip_half_space(out, normal, -glm::dot(normal, apex), eps);
    }
    return out;
}

double distance_to_polygon(const dvec3& p, const Polygon3& poly) {
    if (poly.size() == 1) return glm::length(p - poly[0]);
    double best = std::numeric_limits<double>::infinity();
    const std::size_t n = poly.size();
    for (std::size_t i = 0; i < n; ++i) {
        const dvec3 a = poly[i];
        const dvec3 ab = poly[(i + 1) % n] - a;
        const double len2 = glm::dot(ab, ab);
        const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
        best = std::min(best, glm::length(p - (a + ab * t)));
    }
    if (n < 3) return best;
    // Inside the polygon's outline: the distance to its plane.
    const dvec3 g = aperture_clip_centroid(poly);
    dvec3 normal(0.0);
    for (std::size_t i = 0; i < n; ++i) normal += glm::cross(poly[i] - g, poly[(i + 1) % n] - g);
    const double len = glm::length(normal);
    if (!(len > 0.0)) return best;
    normal /= len;
    const dvec3 q = p - normal * glm::dot(p - g, normal);
    for (std::size_t i = 0; i < n; ++i) {
        const dvec3 edge = poly[(i + 1) % n] - poly[i];
        if (glm::dot(glm::cross(edge, q - poly[i]), normal) < 0.0) return best;
    }
    return std::min(best, std::abs(glm::dot(p - g, normal)));
}

namespace {

// The largest cosine between axis and the directions a + u (b - a), u in
// [0, 1] (a, b from the apex): at an end, or where the axis projected on
// their plane falls between them.
double aperture_clip_segment_cos(const dvec3& axis, const dvec3& a, const dvec3& b) {
    const double ends = std::max(glm::dot(axis, glm::normalize(a)), glm::dot(axis, glm::normalize(b)));
    const dvec3 m = glm::cross(a, b);
    const double len = glm::length(m);
    if (!(len > 1e-300)) return ends;
    const dvec3 unit_m = m / len;
    const dvec3 in_plane = axis - unit_m * glm::dot(axis, unit_m);
    const bool between =
        glm::dot(glm::cross(a, in_plane), unit_m) >= 0.0 && glm::dot(glm::cross(in_plane, b), unit_m) >= 0.0;
    return between ? std::max(ends, glm::length(in_plane)) : ends;
}

}  // namespace

double max_cos_to_polygon(const dvec3& apex, const dvec3& axis, const Polygon3& poly) {
    const std::size_t n = poly.size();
    if (n == 1) return glm::dot(axis, glm::normalize(poly[0] - apex));
    double best = -1.0;
    for (std::size_t i = 0; i < n; ++i) {
        best = std::max(best, aperture_clip_segment_cos(axis, poly[i] - apex, poly[(i + 1) % n] - apex));
    }
    if (n < 3) return best;
    // The ray along the axis meets the polygon's plane inside its outline.
    const dvec3 g = aperture_clip_centroid(poly);
    dvec3 normal(0.0);
    for (std::size_t i = 0; i < n; ++i) normal += glm::cross(poly[i] - g, poly[(i + 1) % n] - g);
    const double facing = glm::dot(normal, axis);
    if (facing == 0.0) return best;
    const double t = glm::dot(normal, g - apex) / facing;
    if (!(t > 0.0)) return best;
    const dvec3 q = apex + axis * t;
    for (std::size_t i = 0; i < n; ++i) {
        if (glm::dot(glm::cross(poly[(i + 1) % n] - poly[i], q - poly[i]), normal) < 0.0) return best;
    }
    return 1.0;
}

math::PortalRect transform_rect(const math::dmat4& m, const math::PortalRect& rect) {
    math::PortalRect out = rect;
    out.center = dvec3(m * math::dvec4(rect.center, 1.0));
    out.normal = dvec3(m * math::dvec4(rect.normal, 0.0));
    out.up = dvec3(m * math::dvec4(rect.up, 0.0));
    out.depth = 0.0;
    return out;
}

}  // namespace impossible::lights
