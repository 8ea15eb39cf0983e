// Oblique near-plane clipping: a projection whose near plane is an arbitrary
// eye-space plane, used to clip a portal's target room at the target portal's
// plane without user clip planes.
//
// Source: Eric Lengyel, "Oblique View Frustum Depth Projection and Clipping",
// Journal of Game Development 1(2), 2005. The method replaces the third row of
// the projection so that the near clipping plane of clip space becomes the
// given plane C, and scales C so that the far plane moves as little as the
// frustum allows.
//
// Conventions: eye space as in conventions.hpp (eye at the origin looking
// along -Z); the plane is (a, b, c, d) with dot(plane, (p, 1)) > 0 for the
// points to keep (in front), e.g. transform_plane(view, portal_plane(B)).
// The projection must be a perspective one with w_clip = -z_eye (those of
// projection.hpp).
//
// Precondition for the oblique plane: the eye is strictly behind the plane
// (plane.w < 0). Otherwise the near plane would have to pass through or in
// front of the eye, which a projection cannot do; both functions then return
// the projection unchanged (the spec's "otherwise no plane clips").
#pragma once

#include "math/conventions.hpp"

namespace impossible::math {

// For the classic OpenGL projection (clip volume -w ≤ z ≤ w), Lengyel's
// formula: row3' = a·C - row4 with a = 2·(row4·Q)/(C·Q), where Q is the corner
// of the original far plane on the positive side of C. Points on C get depth
// -1; the new far plane passes through Q and through the line where C meets
// the eye plane z = 0, so every point of the original frustum that lies in
// front of C stays inside (none is lost to the far plane), the far corner Q
// keeps depth 1.
dmat4 oblique_standard(const dmat4& projection, const dvec4& plane_eye);

// For reversed-Z with glClipControl ZERO_TO_ONE (clip volume 0 ≤ z ≤ w,
// depth 1 at the near plane): the near clip is z_c ≤ w_c, i.e.
// (row4 - row3)·p ≥ 0, so row3' = row4 - a·C makes C the near plane (depth
// 1 on it, < 1 in front, > 1 behind). The far clip z_c ≥ 0 becomes the plane
// row4 - a·C, which passes through the line where C meets z = 0. With an
// infinite far plane Q is the far corner *at infinity*, the direction
// (±tan·aspect, ±tan, -1, 0) towards C's positive side, and a = (row4·Q)/(C·Q)
// makes the new far plane contain that direction: depth stays > 0 for every
// finite point of the frustum in front of C and reaches 0 only at infinity
// along the corner direction Q. Along other directions depth tends to a
// positive limit instead of 0, so the infinite far plane is kept (nothing is
// far-clipped) at the price of some depth range.
dmat4 oblique_reversed_z(const dmat4& projection, const dvec4& plane_eye);

}  // namespace impossible::math
