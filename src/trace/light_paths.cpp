// Light paths to a surface point (light_paths.hpp): followed depth first
// from the point's room, each checked by its shadow ray, leg by leg.
#include "trace/light_paths.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

#include "shading/lighting.hpp"
#include "shading/shading.hpp"
#include "trace/intersect.hpp"
#include "trace/nearest.hpp"

namespace impossible::trace {

namespace {

// One portal of a light path: the portal the shadow ray meets, and whether
// it is reflected there (a mirror, or a window's reflected branch) or passes
// through (a door, or a window's through branch).
struct LightStep {
    int portal = -1;
    bool reflect = false;
};

// A path's first portals: the room reached, M (the point's room's
// coordinates → that room's), M⁻¹, and the product of the portals' factors.
struct PathPrefix {
    int room = -1;
    dmat4 to_room{1.0};
    dmat4 from_room{1.0};
    dvec3 factor{1.0};
};

// A portal rectangle's corners, in the point's room's coordinates.
using Corners = std::array<dvec3, 4>;

// What every path to one point shares: the point, the depth, the shadow
// rays' start tolerance, the path being followed, and the sum so far. The
// path's aperture: the four planes through the point and each edge of each
// of its portals' images (unit normals, towards the rectangle), which every
// shadow ray of the path lies inside.
struct LightSearch {
    const Scene& scene;
    const FrameObjects* objects;
    LitPoint at;
    int depth = 0;
    double tolerance = 0.0;  // shading::shadow_ray_start_tolerance(at.point)
    std::array<LightStep, layout::kMaxLightDepth> steps{};
    std::array<dvec3, 4 * layout::kMaxLightDepth> aperture{};
    dvec3 sum{0.0};
};

// How far outside the aperture a corner may lie and still count: the
// hole's face may lie kHolePlaneTolerance off the portal's plane, and the
// nearest searches decide.
constexpr double kApertureSlack = 2.0 * kHolePlaneTolerance;

// The portal's corners mapped by `m` (into the point's room).
Corners corners_of(const ScenePortal& p, const dmat4& m) {
    const dvec3 r = 0.5 * p.rect.width * p.right, u = 0.5 * p.rect.height * p.rect.up;
    const dvec3 c = p.rect.center;
    const Corners local{c - r - u, c + r - u, c + r + u, c - r + u};
    Corners out;
    for (int i = 0; i < 4; ++i) out[i] = dvec3(m * dvec4(local[i], 1.0));
    return out;
}

// Whether some of the rectangle may lie inside the cone of the path's last
// portal (step k - 1): not all its corners outside one of its planes (a
// convex rectangle wholly outside a half-space has no point that a path's
// shadow ray could pass). Only the last portal's planes: testing every
// portal's cost more than it saved where windows fill walls (three_kinds at
// light depth 6: 23 s against 16 s of processor time), and the light's
// image is tested against them all (image_in_aperture). Conservative; the
// nearest searches decide.
bool in_aperture(const LightSearch& s, int k, const Corners& corners) {
    for (int j = std::max(0, 4 * (k - 1)); j < 4 * k; ++j) {
        const dvec3& n = s.aperture[j];
        bool outside = true;
        for (const dvec3& c : corners) outside = outside && glm::dot(n, c - s.at.point) < -kApertureSlack;
        if (outside) return false;
    }
    return true;
}

// The planes through the point and the rectangle's edges, turned towards
// its centre, stored as step k's (a zero normal where the point lies on an
// edge's line: it culls nothing).
void set_aperture(LightSearch& s, int k, const Corners& corners) {
    const dvec3 centre = 0.25 * (corners[0] + corners[1] + corners[2] + corners[3]) - s.at.point;
    for (int i = 0; i < 4; ++i) {
        const dvec3 n = glm::cross(corners[i] - s.at.point, corners[(i + 1) % 4] - s.at.point);
        const double length = glm::length(n);
        const dvec3 unit = length > 0.0 ? n / length : dvec3(0.0);
        s.aperture[4 * k + i] = glm::dot(unit, centre) < 0.0 ? -unit : unit;
    }
}

// A straight piece of a shadow ray, in `room`'s coordinates: origin + t · dir
// with the same t on every leg (the portals' maps are rigid), the light at
// t = 1; clipped, past the first, by the plane of the portal it comes out of.
struct ShadowLeg {
    int room = -1;
    dvec3 origin{0.0};
    dvec3 dir{0.0};
    ClipPlane clip;
};

// The leg beyond `step`'s portal, as a view ray passes it (tracer.cpp): a
// reflection stays in the room, clipped by the portal's plane; a passage
// goes on in the target's room, clipped by the target's plane.
ShadowLeg next_leg(const Scene& scene, const ShadowLeg& leg, const LightStep& step) {
    const ScenePortal& p = scene.portals[step.portal];
    const ScenePortal& beyond = step.reflect ? p : scene.portals[p.target];
    const dmat4& m = step.reflect ? p.reflection : p.transfer;
    ShadowLeg next;
    next.room = beyond.room;
    next.origin = dvec3(m * dvec4(leg.origin, 1.0));
    next.dir = dmat3(m) * leg.dir;
    next.clip.active = true;
    next.clip.plane = beyond.plane;
    next.clip.tolerance = beyond.clip_tolerance;
    return next;
}

// Whether the leg may cross the portal's rectangle from its front at
// 0 < t < 1: a loose test (a hole's face may lie kHolePlaneTolerance off the
// portal's plane) that only skips hopeless paths before any search; the
// nearest searches decide.
bool may_cross(const ScenePortal& p, const ShadowLeg& leg) {
    const double along = glm::dot(p.rect.normal, leg.dir);
    if (!(along < 0.0)) return false;
    const double slack = kHolePlaneTolerance + 1e-6 * (1.0 + glm::length(p.rect.center));
    const double t = -plane_distance(p.plane, leg.origin) / along;
    const double t_slack = slack / -along;
    if (!(t > -t_slack && t < 1.0 + t_slack)) return false;
    const dvec3 v = leg.origin + t * leg.dir - p.rect.center;
    const double side_slack = slack * (1.0 + glm::length(leg.dir) / -along);
    return std::abs(glm::dot(v, p.right)) <= 0.5 * p.rect.width + side_slack &&
           std::abs(glm::dot(v, p.rect.up)) <= 0.5 * p.rect.height + side_slack;
}

// Steps 1 and 2 of layout-format.md, "Lights": the shadow ray from the
// point towards the light's image (k portals, in the point's room) meets
// each portal of the path first, in order, then nothing before the light.
bool shadow_ray_clear(const LightSearch& s, int k, const dvec3& image, double d) {
    // Surfaces within the tolerance of the point do not count: the ray
    // starts that far along.
    ShadowLeg first;
    first.room = s.at.room;
    first.origin = s.at.point + (s.tolerance / d) * (image - s.at.point);
    first.dir = image - first.origin;
    // The cheap tests first, every leg; the legs are mapped again below
    // rather than kept, as few paths get that far.
    ShadowLeg leg = first;
    for (int i = 0; i < k; ++i) {
        if (!may_cross(s.scene.portals[s.steps[i].portal], leg)) return false;
        leg = next_leg(s.scene, leg, s.steps[i]);
    }
    Nearest n;
    leg = first;
    for (int i = 0; i < k; ++i) {
        nearest_for_light(s.scene, s.objects, leg.room, leg.origin, leg.dir, leg.clip, 1.0, n);
        if (!n.found || n.portal != s.steps[i].portal) return false;
        leg = next_leg(s.scene, leg, s.steps[i]);
    }
    nearest_for_light(s.scene, s.objects, leg.room, leg.origin, leg.dir, leg.clip, 1.0, n);
    return !n.found;
}

// Whether the light's image lies inside the aperture of the path's k
// portals (with the slack of in_aperture): a shadow ray to it can pass them.
bool image_in_aperture(const LightSearch& s, int k, const dvec3& image) {
    const dvec3 v = image - s.at.point;
    for (int j = 0; j < 4 * k; ++j)
        if (glm::dot(s.aperture[j], v) < -kApertureSlack) return false;
    return true;
}

// The contribution of `light` (of the prefix's room) along the path of the
// prefix's k portals, where its shadow ray is clear.
void add_light(LightSearch& s, const PathPrefix& prefix, int k, const layout::Light& light) {
    const dvec3 image = dvec3(prefix.from_room * dvec4(light.position, 1.0));
    if (!image_in_aperture(s, k, image)) return;
    const dvec3 v = image - s.at.point;
    const double d = glm::length(v);
    if (!(d > 0.0)) return;
    const dvec3 w = v / d;
    if (!(glm::dot(s.at.normal, w) > 0.0)) return;  // adds nothing: no shadow ray
    const dvec3 to_light = glm::normalize(dmat3(prefix.to_room) * w);
    dvec3 c = shading::light_contribution(light, prefix.factor, s.at.normal, w, d, to_light);
    if (c == dvec3(0.0)) return;  // out of range or of the cone, or black
    // A light within the tolerance: no surface counts, so only k = 0 reaches it.
    if (d <= s.tolerance ? k > 0 : !shadow_ray_clear(s, k, image, d)) return;
    // 1 / d² may overflow that close (and times a zero make NaN): a channel
    // the light reaches saturates, any other stays 0.
    if (!std::isfinite(c.x + c.y + c.z)) {
        const bool reaches = shading::spot_factor(light, to_light) > 0.0 && light.intensity > 0.0 &&
                             (light.range <= 0.0 || d < light.range);
        for (int ch = 0; ch < 3; ++ch)
            if (!std::isfinite(c[ch])) c[ch] = reaches && light.color[ch] * prefix.factor[ch] > 0.0 ? 1e300 : 0.0;
    }
    s.sum += c;
}

void visit_paths(LightSearch& s, const PathPrefix& prefix, int k);

// Follows the prefix through portal step k (its matrix m, m's inverse, the
// room beyond and the portal's factor) unless the factor falls too low.
void follow_step(LightSearch& s, const PathPrefix& prefix, int k, const dmat4& m, const dmat4& m_inverse, int room,
                 const dvec3& factor) {
    PathPrefix next{room, m * prefix.to_room, prefix.from_room * m_inverse, prefix.factor * factor};
    if (shading::max_channel(next.factor) < shading::kMinLightFactor) return;
    visit_paths(s, next, k + 1);
}

// The lights of the prefix's room, then every longer path: through each
// portal of the room that the point's image lies in front of (a shadow ray
// meets a portal only from its front) and whose image lies partly inside
// the cone of the path's last portal, a window both ways, its reflection first.
void visit_paths(LightSearch& s, const PathPrefix& prefix, int k) {
    for (const layout::Light& light : s.scene.rooms[prefix.room].lights) add_light(s, prefix, k, light);
    if (k >= s.depth) return;
    const dvec3 seen = dvec3(prefix.to_room * dvec4(s.at.point, 1.0));
    for (int index : s.scene.rooms[prefix.room].portals) {
        const ScenePortal& p = s.scene.portals[index];
        if (!(plane_distance(p.plane, seen) > -p.clip_tolerance)) continue;
        const Corners corners = corners_of(p, prefix.from_room);
        if (!in_aperture(s, k, corners)) continue;
        set_aperture(s, k, corners);
        s.steps[k].portal = index;
        if (p.kind != layout::PortalKind::Door) {
            s.steps[k].reflect = true;
            const dvec3 factor = p.kind == layout::PortalKind::Mirror ? p.tint : dvec3(p.reflectance);
            follow_step(s, prefix, k, p.reflection, p.reflection, prefix.room, factor);
        }
        if (p.kind != layout::PortalKind::Mirror) {
            s.steps[k].reflect = false;
            const ScenePortal& b = s.scene.portals[p.target];
            const dvec3 factor = p.kind == layout::PortalKind::Door ? dvec3(1.0) : (1.0 - p.reflectance) * p.tint;
            follow_step(s, prefix, k, p.transfer, b.transfer, b.room, factor);
        }
    }
}

}  // namespace

dvec3 light_sum(const Scene& scene, const FrameObjects* objects, const LitPoint& at, int light_depth) {
    LightSearch s{scene, objects, at};
    s.depth = std::clamp(light_depth, 0, layout::kMaxLightDepth);
    s.tolerance = shading::shadow_ray_start_tolerance(at.point);
    PathPrefix start;
    start.room = at.room;
    visit_paths(s, start, 0);
    return s.sum;
}

}  // namespace impossible::trace
