// Rigid transforms (see rigid.hpp).
#include "math/rigid.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace impossible::math {

dmat4 rigid_inverse(const dmat4& m) {
    const dmat3 rt = glm::transpose(dmat3(m));
    dmat4 inv(rt);
    inv[3] = dvec4(-(rt * dvec3(m[3])), 1.0);
    return inv;
}

dmat4 orthonormalize_rigid(const dmat4& m) {
    const dvec3 x = glm::normalize(dvec3(m[0]));
    const dvec3 y0 = dvec3(m[1]);
    const dvec3 y = glm::normalize(y0 - glm::dot(y0, x) * x);
    const dvec3 z = glm::cross(x, y);
    dmat4 out(1.0);
    out[0] = dvec4(x, 0.0);
    out[1] = dvec4(y, 0.0);
    out[2] = dvec4(z, 0.0);
    out[3] = dvec4(dvec3(m[3]), 1.0);
    return out;
}

double orthonormality_error(const dmat4& m) {
    const dmat3 r(m);
    const dmat3 g = glm::transpose(r) * r;
    double err = 0.0;
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) err = std::max(err, std::abs(g[c][k] - (c == k ? 1.0 : 0.0)));
    return err;
}

double max_abs_difference(const dmat4& m, const dmat4& n) {
    double err = 0.0;
    for (int c = 0; c < 4; ++c)
        for (int k = 0; k < 4; ++k) err = std::max(err, std::abs(m[c][k] - n[c][k]));
    return err;
}

}  // namespace impossible::math
