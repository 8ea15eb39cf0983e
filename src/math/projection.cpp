// Perspective projections and pixel rays (see projection.hpp).
#include "math/projection.hpp"

#include <cmath>

namespace impossible::math {

namespace {
double tan_half_fov(const Frustum& f) { return std::tan(radians(0.5 * f.fov_y_deg)); }
}  // namespace

dmat4 perspective_reversed_z(const Frustum& f) {
    // clip = (x·s/aspect, y·s, near, -z): depth = near / -z, 1 at the near
    // plane and tending to 0 at infinity.
    const double s = 1.0 / tan_half_fov(f);
    dmat4 m(0.0);
    m[0][0] = s / f.aspect;
    m[1][1] = s;
    m[2][3] = -1.0;
    m[3][2] = f.near;
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
    return m;
}

dvec3 image_point_ray_eye(const Frustum& f, int width, int height, double x, double y) {
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
