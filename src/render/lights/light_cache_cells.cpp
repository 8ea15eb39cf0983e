// What the light cache knows of a cell: whether an image's aperture and its
// props' shadows leave it wholly lit (light_cache_cells.hpp).
#include "render/lights/light_cache_cells.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include "lights/lit_region.hpp"
#include "math/portal.hpp"
#include "render/lights/shadow_regions.hpp"

namespace impossible::render {
namespace {

// Off a plane by more than this (metres) counts as off it.
constexpr double kSide = 1e-7;

// The planes of the convex hull of `p` (n · x + d <= 0 inside), by trying
// every three of its points.
std::vector<glm::dvec4> hull_planes(const std::array<glm::dvec3, 16>& p) {
    std::vector<glm::dvec4> out;
    for (size_t a = 0; a < p.size(); ++a)
        for (size_t b = a + 1; b < p.size(); ++b)
            for (size_t c = b + 1; c < p.size(); ++c) {
                glm::dvec3 n = glm::cross(p[b] - p[a], p[c] - p[a]);
                const double len = glm::length(n);
                if (len < 1e-12) continue;
                n /= len;
                double lo = 0.0, hi = 0.0;
                for (const glm::dvec3& q : p) {
                    const double s = glm::dot(n, q - p[a]);
                    lo = std::min(lo, s);
                    hi = std::max(hi, s);
                }
                if (lo < -kSide && hi > kSide) continue;
                if (hi > kSide) n = -n;  // every point on the plane's inner side
                const glm::dvec4 plane(n, -glm::dot(n, p[a]));
                const bool seen = std::any_of(out.begin(), out.end(), [&](const glm::dvec4& o) {
                    return glm::length(glm::dvec3(o) - n) < 1e-9 && std::abs(o.w - plane.w) < 1e-9;
                });
                if (!seen) out.push_back(plane);
            }
    return out;
}

}  // namespace

CellLight aperture_light(const lights::LightImage& image, const glm::dvec3& origin,
                         const std::array<glm::dvec3, 4>& corners) {
    if (image.apertures.empty()) return CellLight::Lit;
    return through_rect(image.apertures.front().rect, image.position, origin, corners);
}

CellLight through_rect(const math::PortalRect& rect, const glm::dvec3& position, const glm::dvec3& origin,
                       const std::array<glm::dvec3, 4>& corners) {
    const glm::dvec3 light = position - origin, c = rect.center - origin;
    // lighting.frag.glsl's light_aperture_open: lit where p lies beyond the
    // aperture's plane (n · (p - c) > 0), with L' before it, and within the
    // pyramid from L' through the rectangle.
    if (glm::dot(rect.normal, c - light) <= 0.0) return CellLight::Dark;
    std::array<glm::dvec4, 5> planes;  // n · p + d > 0 inside
    planes[4] = glm::dvec4(rect.normal, -glm::dot(rect.normal, c));
    math::dvec3 a[8];  // the rectangle's corners first, in order round it
    math::box_corners(rect, a);
    for (size_t k = 0; k < 4; ++k) a[k] -= origin;
    for (size_t k = 0; k < 4; ++k) {
        glm::dvec3 n = glm::normalize(glm::cross(a[k] - light, a[(k + 1) % 4] - light));
        if (glm::dot(n, c - light) < 0.0) n = -n;
        planes[k] = glm::dvec4(n, -glm::dot(n, light));
    }
    bool all_inside = true;
    for (const glm::dvec4& plane : planes) {
        int outside = 0;
        for (const glm::dvec3& p : corners) {
            const double s = glm::dot(glm::dvec3(plane), p) + plane.w;
            if (s < -kSide) ++outside;
            if (s <= kSide) all_inside = false;
        }
        if (outside == 4) return CellLight::Dark;
    }
    return all_inside ? CellLight::Lit : CellLight::Edge;
}

ShadowHull make_hull(const std::array<glm::dvec3, 16>& corners) {
    ShadowHull h;
    h.points = corners;
    h.planes = hull_planes(corners);
    h.lo = h.hi = corners[0];
    for (const glm::dvec3& p : corners) {
        h.lo = glm::min(h.lo, p);
        h.hi = glm::max(h.hi, p);
    }
    return h;
}

bool hull_meets(const ShadowHull& hull, const std::array<glm::dvec3, 4>& q) {
    glm::dvec3 lo = q[0], hi = q[0];
    for (const glm::dvec3& p : q) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    for (int i = 0; i < 3; ++i)
        if (lo[i] > hull.hi[i] + kSide || hi[i] < hull.lo[i] - kSide) return false;
    // Separating planes: the hull's faces, the cell's plane, and the planes
    // through the cell's edges square to it. Others are not tried: the test
    // may find a meeting where there is none, never the reverse.
    for (const glm::dvec4& plane : hull.planes)
        if (std::all_of(q.begin(), q.end(),
                        [&](const glm::dvec3& p) { return glm::dot(glm::dvec3(plane), p) + plane.w > kSide; }))
            return false;
    const glm::dvec3 n = glm::cross(q[1] - q[0], q[3] - q[0]);
    const auto side_of = [&](const glm::dvec3& normal, const glm::dvec3& at) {
        bool above = true, below = true;
        for (const glm::dvec3& p : hull.points) {
            const double s = glm::dot(normal, p - at);
            above = above && s > kSide * glm::length(normal);
            below = below && s < -kSide * glm::length(normal);
        }
        return above || below;
    };
    if (side_of(n, q[0])) return false;
    const glm::dvec3 centre = 0.25 * (q[0] + q[1] + q[2] + q[3]);
    for (size_t k = 0; k < 4; ++k) {
        glm::dvec3 e = glm::cross(q[(k + 1) % 4] - q[k], n);
        if (glm::dot(e, centre - q[k]) > 0.0) e = -e;  // outwards
        bool outside = true;
        for (const glm::dvec3& p : hull.points) outside = outside && glm::dot(e, p - q[k]) > kSide * glm::length(e);
        if (outside) return false;
    }
    return true;
}

ImageShadows image_shadows(const lights::LightImage& image, const std::vector<scene::CellObjects>& objects,
                           const glm::dvec3& origin, const std::pair<glm::dvec3, glm::dvec3>& bounds, int map_size) {
    ImageShadows out;
    if (map_size <= 0) return out;
    const double reach = lights::light_reach(image.position, bounds.first, bounds.second);
    // As shadow_regions.cpp's: each leg's props, grown by four map texels.
    for (size_t i = 0; i < image.rooms.size(); ++i) {
        const glm::dmat4 to_c = glm::inverse(image.to_room[i]);
        for (const scene::CellObject& object : objects[static_cast<size_t>(image.rooms[i])].objects) {
            std::array<glm::dvec3, 16> hull;
            if (!lights::shadow_region(image.position, to_c, object.lo, object.hi, reach, shadow_grow_angle(map_size),
                                       hull)) {
                out.anywhere = true;
                return out;
            }
            for (glm::dvec3& p : hull) p -= origin;
            ShadowHull h = make_hull(hull);
            // The core: the box less twice the hull's margin on every side.
            const glm::dmat4 from_box = glm::translate(glm::dmat4(1.0), -origin) * to_c;
            double far = 0.0;
            for (int k = 0; k < 8; ++k) {
                const glm::dvec3 corner((k & 1) ? object.hi.x : object.lo.x, (k & 2) ? object.hi.y : object.lo.y,
                                        (k & 4) ? object.hi.z : object.lo.z);
                far = std::max(far, glm::length(glm::dvec3(to_c * glm::dvec4(corner, 1.0)) - image.position));
            }
            const double margin = 2.0 * (shadow_grow_angle(map_size) * far + 1e-4);
            h.from_c = glm::inverse(from_box);
            h.core_lo = object.lo + margin;
            h.core_hi = object.hi - margin;
            out.hulls.push_back(std::move(h));
        }
    }
    return out;
}

bool in_core_shadow(const ShadowHull& hull, const glm::dvec3& p, const glm::dvec3& light) {
    const glm::dvec3 a(hull.from_c * glm::dvec4(p, 1.0)), b(hull.from_c * glm::dvec4(light, 1.0));
    double t0 = 0.0, t1 = 1.0;  // the slabs' test
    for (int i = 0; i < 3; ++i) {
        if (hull.core_lo[i] >= hull.core_hi[i]) return false;
        const double d = b[i] - a[i];
        if (std::abs(d) < 1e-15) {
            if (a[i] <= hull.core_lo[i] || a[i] >= hull.core_hi[i]) return false;
            continue;
        }
        double u0 = (hull.core_lo[i] - a[i]) / d, u1 = (hull.core_hi[i] - a[i]) / d;
        if (u0 > u1) std::swap(u0, u1);
        t0 = std::max(t0, u0);
        t1 = std::min(t1, u1);
        if (t0 >= t1) return false;
    }
    return true;
}

CellLight cell_light(const lights::LightImage& image, const ImageShadows& shadows, const glm::dvec3& origin,
                     const std::array<glm::dvec3, 4>& corners) {
    const CellLight through = aperture_light(image, origin, corners);
    if (through != CellLight::Lit) return through;
    // A blocker (of an image with no aperture: its one leg is the whole
    // segment) darkens where the segment crosses it from its front, the set
    // an aperture lets through.
    bool blocked = false;
    for (const lights::Blocker& b : image.blockers) {
        const CellLight behind = through_rect(b.rect, image.position, origin, corners);
        if (behind == CellLight::Lit) return CellLight::Dark;
        blocked = blocked || behind == CellLight::Edge;
    }
    if (blocked || shadows.anywhere) return CellLight::Edge;
    const glm::dvec3 light = image.position - origin;
    bool meets = false;
    for (const ShadowHull& h : shadows.hulls) {
        if (!hull_meets(h, corners)) continue;
        if (std::all_of(corners.begin(), corners.end(),
                        [&](const glm::dvec3& p) { return in_core_shadow(h, p, light); }))
            return CellLight::Dark;
        meets = true;
    }
    return meets ? CellLight::Edge : CellLight::Lit;
}

glm::dvec3 cached_term(const float* record, const glm::dvec3& p, const glm::dvec3& n) {
    const glm::dvec3 position(record[0], record[1], record[2]);
    const double range = record[3];
    const glm::dvec3 radiance(record[4], record[5], record[6]);
    const double cos_outer = record[7];
    const glm::dvec3 axis(record[8], record[9], record[10]);
    const double inverse_band = record[11];
    const glm::dvec3 v = position - p;
    const double d = std::max(glm::length(v), 1e-30);
    const glm::dvec3 w = v / d;
    double att = 1.0 / (d * d);
    if (range > 0.0) {
        const double r = d / range;
        att *= std::clamp(1.0 - r * r * r * r, 0.0, 1.0);
    }
    double spot = std::clamp((glm::dot(axis, -w) - cos_outer) * inverse_band, 0.0, 1.0);
    spot = cos_outer <= 1.0 ? spot * spot : 1.0;
    return radiance * (std::max(0.0, glm::dot(n, w)) * att * spot);
}

}  // namespace impossible::render
