// The swept test of a moving point against a portal rectangle
// (layout-format.md, "Head, eyes and walking").
//
// A segment p0 → p1 crosses portal P when it passes from d(p0) ≥ 0 to
// d(p1) < 0 (a point exactly on the plane, d = 0, is in front) and the point
// where it meets the plane lies within the rectangle, edges included
// (|x| ≤ width/2 and |y| ≤ height/2 in the portal's frame). Distances are
// d = dot(p - center, normal) as in portal.hpp. Units: metres.
#pragma once

#include <optional>

#include "math/conventions.hpp"
#include "math/portal.hpp"

namespace impossible::math {

struct SegmentCrossing {
    double t = 0.0;    // parameter along p0 → p1, in [0, 1]
    dvec3 point{0.0};  // p0 + t·(p1 - p0), on the plane up to rounding
};

// t = d0 / (d0 - d1): both distances are computed once and the division of
// two same-signed quantities keeps t in [0, 1] without cancellation.
std::optional<SegmentCrossing> segment_crossing(const PortalRect& p, const dvec3& p0, const dvec3& p1);

// A point (assumed on the plane) lies within the rectangle, edges included.
bool within_rectangle(const PortalRect& p, const dvec3& point);

}  // namespace impossible::math
