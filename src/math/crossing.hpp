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

// Whether an eye has door P's inner box faces (layout-format.md, "The portal
// box"): it lies in the box's column (in_column) and the head reaches it
// through the door: the eye is in front of the plane (d ≥ 0), or the segment
// from the head centre to the eye crosses the plane within the rectangle
// (segment_crossing). An eye and head behind a door the head walked round
// have no inner faces: from behind, the door is not there.
bool has_inner_faces(const PortalRect& p, const dvec3& eye, const dvec3& head);

}  // namespace impossible::math
