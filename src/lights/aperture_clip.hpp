// Convex polygons in space for the light images' aperture test
// (light_images.cpp): the part of a portal rectangle that the rays from a
// light's image through the apertures already passed can reach. Double
// precision; every clip keeps what lies within `eps` outside, so rounding
// can only keep too much (the enumeration must be conservative), never
// drop a light path.
#pragma once

#include <vector>

#include "math/portal.hpp"

namespace impossible::lights {

using Polygon3 = std::vector<math::dvec3>;

// The four corners of the front rectangle (depth 0), each half-extent grown by eps.
Polygon3 rect_polygon(const math::PortalRect& rect, double eps);

// The part of a convex polygon where dot(normal, x) + offset >= -eps
// (normal unit). Sutherland and Hodgman with one plane.
Polygon3 clip_half_space(const Polygon3& poly, const math::dvec3& normal, double offset, double eps);

// The part of `poly` (convex, in any plane) inside the cone with apex
// `apex` over the convex polygon `window`: the points x for which the ray
// from apex through x passes through `window` (before or after x). A
// degenerate window (a segment or a point) clips by the edges that are not
// degenerate only (keeping more).
Polygon3 clip_to_cone(const Polygon3& poly, const math::dvec3& apex, const Polygon3& window, double eps);

// The distance from p to the nearest point of a convex planar polygon with
// at least one corner.
double distance_to_polygon(const math::dvec3& p, const Polygon3& poly);

// The largest cosine of the angle between the unit `axis` and the direction
// from `apex` to a point of the convex planar polygon (at least one corner;
// the apex not in its plane): 1 when the ray from apex along axis meets it.
double max_cos_to_polygon(const math::dvec3& apex, const math::dvec3& axis, const Polygon3& poly);

// A rigid transform (or a reflection) applied to a portal rectangle: the
// centre as a point, the normal and up as directions; depth 0.
math::PortalRect transform_rect(const math::dmat4& m, const math::PortalRect& rect);

}  // namespace impossible::lights
