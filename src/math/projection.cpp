// Perspective projections and pixel rays (see projection.hpp).
#include "math/projection.hpp"

#include <cmath>

namespace impossible::math {

namespace {
double tan_half_fov(const Frustum& f) { return std::tan(radians(0.5 * f.fov_y_deg)); }

// The off-axis projection's x and y rows: x_ndc = (2·tx - (r + l)) / (r - l)
// for the tangent tx = x / -z, and the same for y.
void set_off_axis(dmat4& m, const FovTangents& t) {
    m[0][0] = 2.0 / (t.right - t.left);
    m[2][0] = (t.right + t.left) / (t.right - t.left);
    m[1][1] = 2.0 / (t.up - t.down);
    m[2][1] = (t.up + t.down) / (t.up - t.down);
}
}  // namespace

FovTangents fov_tangents(const FovAngles& a) {
    return {std::tan(radians(a.left)), std::tan(radians(a.right)), std::tan(radians(a.up)), std::tan(radians(a.down))};
}

dmat4 perspective_reversed_z(const Frustum& f) {
    // clip = (x·s/aspect, y·s, near, -z): depth = near / -z, 1 at the near
    // plane and tending to 0 at infinity.
    const double s = 1.0 / tan_half_fov(f);
    dmat4 m(0.0);
    m[0][0] = s / f.aspect;
    m[1][1] = s;
    m[2][3] = -1.0;
    m[3][2] = f.near;
    if (f.tangents) set_off_axis(m, *f.tangents);
    return m;
}

dmat4 perspective_standard(const Frustum& f, double far) {
    const double s = 1.0 / tan_half_fov(f);
    dmat4 m(0.0);
    m[0][0] = s / f.aspect;
    m[1][1] = s;
    m[2][2] = -(far + f.near) / (far - f.near);
    m[2][3] = -1.0;
    m[3][2] = -2.0 * far * f.near / (far - f.near);
    if (f.tangents) set_off_axis(m, *f.tangents);
    return m;
}

dvec3 image_point_ray_eye(const Frustum& f, int width, int height, double x, double y) {
    if (f.tangents) {
        const FovTangents& t = *f.tangents;
        return {t.left + (x / width) * (t.right - t.left), t.up - (y / height) * (t.up - t.down), -1.0};
    }
    const double t = tan_half_fov(f);
    const double aspect = static_cast<double>(width) / static_cast<double>(height);
    const double nx = 2.0 * (x / width) - 1.0;   // -1 at the left edge
    const double ny = 1.0 - 2.0 * (y / height);  // +1 at the top edge
    return {nx * t * aspect, ny * t, -1.0};
}

dvec3 pixel_ray_eye(const Frustum& f, int width, int height, int i, int j) {
    return image_point_ray_eye(f, width, height, i + 0.5, j + 0.5);
}

}  // namespace impossible::math
