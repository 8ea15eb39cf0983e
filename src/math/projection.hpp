// Perspective projections and pixel rays (cli.md: "Pixel (i, j) of an eye
// image, row 0 at the top, is the ray through the pixel's centre").
#pragma once

#include "math/conventions.hpp"

namespace impossible::math {

struct Frustum {
    double fov_y_deg = 90.0;  // vertical field of view, symmetric
    double aspect = 16.0 / 9.0;  // width / height
    double near = 0.01;
};

// Reversed-Z with an infinite far plane, for glClipControl(GL_LOWER_LEFT,
// GL_ZERO_TO_ONE): depth 1 at the near plane, tending to 0 at infinity.
dmat4 perspective_reversed_z(const Frustum& f);

// The classic OpenGL projection (depth -1..1 from near to far).
dmat4 perspective_standard(const Frustum& f, double far);

// Direction in eye space (not normalised; z = -1) of the ray through the
// centre of pixel (i, j) of a width × height eye image, row 0 at the top.
dvec3 pixel_ray_eye(const Frustum& f, int width, int height, int i, int j);

}  // namespace impossible::math
