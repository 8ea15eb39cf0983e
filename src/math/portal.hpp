// Portal frames and transfer matrices (layout-format.md, "The portal frame and
// the transfer matrix", "The portal box").
//
// For a portal P: n = normal, u = up (orthogonal to n), r = u × n, and
// T_P = [r u n center]. Signed distance d = dot(p - center, n) > 0 in front.
// M_AB = T_B · R_y(180°) · T_A⁻¹ maps what lies in front of A onto what lies
// behind B.
#pragma once

#include "math/conventions.hpp"

namespace impossible::math {

struct PortalRect {
    dvec3 center{0.0};
    dvec3 normal{0.0, 0.0, 1.0};  // unit
    dvec3 up{0.0, 1.0, 0.0};      // unit, orthogonal to normal
    double width = 1.0;
    double height = 2.0;
    double depth = 0.25;  // the box reaches from d = 0 to d = -depth
};

dvec3 portal_right(const PortalRect& p);  // u × n
dmat4 portal_frame(const PortalRect& p);  // T_P
dmat4 portal_frame_inverse(const PortalRect& p);

// M_AB = T_B · R_y(180°) · T_A⁻¹. Rigid. Exactly the identity for two
// coincident portals with opposite normals and the same up.
dmat4 transfer_matrix(const PortalRect& a, const PortalRect& b);

// M_P = T_P · S · T_P⁻¹ with S = diag(1, 1, -1): the reflection in the
// portal's plane (a mirror's, or a window's reflected branch). Its own
// inverse; it turns handedness (layout-format.md, "Mirrors and windows").
dmat4 reflection_matrix(const PortalRect& p);

double signed_distance(const PortalRect& p, const dvec3& point);

// The plane as (n, -dot(n, center)): dot(plane, (p, 1)) = signed distance.
dvec4 portal_plane(const PortalRect& p);

// A plane (a, b, c, d) carried by the rigid transform m: the plane of the
// mapped points. (Multiply by the inverse transpose.)
dvec4 transform_plane(const dmat4& m, const dvec4& plane);

// The eye's position, in the portal's frame, lies over the rectangle
// (|x| ≤ w/2, |y| ≤ h/2) and not behind the back face (d ≥ -depth).
bool in_column(const PortalRect& p, const dvec3& eye);

// The eight corners of the box: first the four of the front rectangle
// (d = 0), then the four of the back face (d = -depth), each in the order
// (-r,-u), (+r,-u), (+r,+u), (-r,+u).
void box_corners(const PortalRect& p, dvec3 out[8]);

}  // namespace impossible::math
