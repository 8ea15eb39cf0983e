// Portal frames and transfer matrices (see portal.hpp).
#include "math/portal.hpp"

#include <cmath>

#include <glm/geometric.hpp>

namespace impossible::math {

dvec3 portal_right(const PortalRect& p) { return glm::cross(p.up, p.normal); }

dmat4 portal_frame(const PortalRect& p) {
    dmat4 t(1.0);
    t[0] = dvec4(portal_right(p), 0.0);
    t[1] = dvec4(p.up, 0.0);
    t[2] = dvec4(p.normal, 0.0);
    t[3] = dvec4(p.center, 1.0);
    return t;
}

dmat4 portal_frame_inverse(const PortalRect& p) {
    // Rows r, u, n; translation -(r·c, u·c, n·c).
    const dvec3 r = portal_right(p);
    dmat4 inv(1.0);
    for (int c = 0; c < 3; ++c) {
        inv[c][0] = r[c];
        inv[c][1] = p.up[c];
        inv[c][2] = p.normal[c];
    }
    inv[3] = dvec4(-glm::dot(r, p.center), -glm::dot(p.up, p.center), -glm::dot(p.normal, p.center), 1.0);
    return inv;
}

dmat4 reflection_matrix(const PortalRect& p) {
    // p' = p - 2 · dot(p - c, n) · n: linear part I - 2nnᵀ, translation
    // 2 · dot(c, n) · n (fewer roundings than the three-matrix product).
    const dvec3& n = p.normal;
    dmat4 m(1.0);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) m[c][r] -= 2.0 * n[c] * n[r];
    const dvec3 t = 2.0 * glm::dot(p.center, n) * n;
    m[3] = dvec4(t, 1.0);
    return m;
}

dmat4 transfer_matrix(const PortalRect& a, const PortalRect& b) {
    // R_y(180°) negates x and z, so T_B · R_y(180°) has the columns
    // (-r_B, u_B, -n_B, c_B). Its rotation times R_Aᵀ, and the translation
    // c_B - R · c_A, computed directly (fewer roundings than multiplying the
    // three matrices).
    const dvec3 ra = portal_right(a);
    const dvec3 rb = portal_right(b);
    const dvec3 bx = -rb, by = b.up, bz = -b.normal;
    if (bx == ra && by == a.up && bz == a.normal && a.center == b.center) {
        return dmat4(1.0);  // coincident, opposite portals: exactly the identity
    }
    // R = Bx·raᵀ + By·uaᵀ + Bz·naᵀ, so column j of R is Bx·ra[j] + By·ua[j] + Bz·na[j].
    dmat3 rot;
    for (int j = 0; j < 3; ++j) rot[j] = bx * ra[j] + by * a.up[j] + bz * a.normal[j];
    dmat4 m(rot);
    m[3] = dvec4(b.center - rot * a.center, 1.0);
    return m;
}

double signed_distance(const PortalRect& p, const dvec3& point) { return glm::dot(point - p.center, p.normal); }

dvec4 portal_plane(const PortalRect& p) { return dvec4(p.normal, -glm::dot(p.normal, p.center)); }

dvec4 transform_plane(const dmat4& m, const dvec4& plane) {
    // For p' = R·p + t: n·p + d = (R·n)·p' - (R·n)·t + d.
    const dvec3 n = dmat3(m) * dvec3(plane);
    return dvec4(n, plane.w - glm::dot(n, dvec3(m[3])));
}

bool in_column(const PortalRect& p, const dvec3& eye) {
    const dvec3 v = eye - p.center;
    return std::abs(glm::dot(v, portal_right(p))) <= 0.5 * p.width && std::abs(glm::dot(v, p.up)) <= 0.5 * p.height &&
           glm::dot(v, p.normal) >= -p.depth;
}

void box_corners(const PortalRect& p, dvec3 out[8]) {
    const dvec3 r = (0.5 * p.width) * portal_right(p);
    const dvec3 u = (0.5 * p.height) * p.up;
    const dvec3 back = -p.depth * p.normal;
    const dvec3 front[4] = {p.center - r - u, p.center + r - u, p.center + r + u, p.center - r + u};
    for (int k = 0; k < 4; ++k) {
        out[k] = front[k];
        out[k + 4] = front[k] + back;
    }
}

}  // namespace impossible::math
