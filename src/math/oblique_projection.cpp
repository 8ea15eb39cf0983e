// Oblique near-plane clipping (Lengyel 2005); see oblique_projection.hpp.
#include "math/oblique_projection.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace impossible::math {

namespace {

dvec4 row(const dmat4& m, int r) { return dvec4(m[0][r], m[1][r], m[2][r], m[3][r]); }

void set_row(dmat4& m, int r, const dvec4& v) {
    for (int c = 0; c < 4; ++c) m[c][r] = v[c];
}

// The plane scale a = k·(row4·Q)/(C·Q), with Q the clip-space corner
// (sgn C'x, sgn C'y, far_z, 1) taken back to eye space. When C·Q ≤ 0 no point
// of the frustum is in front of C: any positive a then gives the right near
// plane (which clips everything), and one of the plane's own scale is used.
double plane_scale(const dmat4& projection, const dvec4& plane, double far_z, double k) {
    const dmat4 inv = glm::inverse(projection);
    const dvec4 plane_clip = glm::transpose(inv) * plane;  // C' = P⁻ᵀ·C
    const dvec4 q_clip(plane_clip.x >= 0.0 ? 1.0 : -1.0, plane_clip.y >= 0.0 ? 1.0 : -1.0, far_z, 1.0);
    const dvec4 q = inv * q_clip;
    const double w_q = glm::dot(row(projection, 3), q);  // = q_clip.w = 1 up to rounding
    const double c_q = glm::dot(plane, q);
    if (c_q > 0.0) return k * w_q / c_q;
    return k * w_q / (glm::length(dvec3(plane)) * glm::length(dvec3(q)) + std::abs(plane.w) + 1.0);
}

}  // namespace

dmat4 oblique_standard(const dmat4& projection, const dvec4& plane_eye) {
    if (!(plane_eye.w < 0.0)) return projection;
    const double a = plane_scale(projection, plane_eye, 1.0, 2.0);
    dmat4 m = projection;
    set_row(m, 2, a * plane_eye - row(projection, 3));
    return m;
}

dmat4 oblique_reversed_z(const dmat4& projection, const dvec4& plane_eye) {
    if (!(plane_eye.w < 0.0)) return projection;
    const double a = plane_scale(projection, plane_eye, 0.0, 1.0);
    dmat4 m = projection;
    set_row(m, 2, row(projection, 3) - a * plane_eye);
    return m;
}

}  // namespace impossible::math
