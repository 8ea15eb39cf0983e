// Perspective projections and pixel rays (cli.md: "Pixel (i, j) of an eye
// image, row 0 at the top, is the ray through the pixel's centre").
//
// Eye space as in conventions.hpp: looking along -Z, +Y up, +X right.
// Matrices map eye space to clip space (p_clip = P · p_eye, w_clip = -z_eye).
// Pixel (i, j): i is the column (0 at the left), j the row (0 at the top).
// The rays use aspect = width / height of the image itself (cli.md); a
// renderer builds its Frustum with the same aspect so both agree.
#pragma once

#include <optional>

#include "math/conventions.hpp"

namespace impossible::math {

// An eye's field of view as OpenXR's XrFovf gives it: the angles in degrees
// of the frustum's left, right, top and bottom planes from the view axis,
// positive to the right and up (so left and down are usually negative).
struct FovAngles {
    double left = -45.0, right = 45.0, up = 45.0, down = -45.0;
    bool operator==(const FovAngles&) const = default;
};

// The tangents of those angles: the image plane at z = -1 spans
// x in [left, right] and y in [down, up].
struct FovTangents {
    double left = -1.0, right = 1.0, up = 1.0, down = -1.0;
};
FovTangents fov_tangents(const FovAngles& angles);

// The same angles for the other eye (mirrored in the head's mid plane).
inline FovAngles mirrored(const FovAngles& a) { return {-a.right, -a.left, a.up, a.down}; }

struct Frustum {
    Frustum() = default;
    Frustum(double fov_y, double aspect_ratio, double near_distance, std::optional<FovTangents> off_axis = std::nullopt)
        : fov_y_deg(fov_y), aspect(aspect_ratio), near(near_distance), tangents(off_axis) {}

    double fov_y_deg = 90.0;     // vertical field of view, symmetric
    double aspect = 16.0 / 9.0;  // width / height
    double near = 0.01;
    // An asymmetric frustum (headset optics): when set, it replaces
    // fov_y_deg and aspect; the image spans these tangents whatever its
    // width and height. Unset, the symmetric arithmetic is exactly as before.
    std::optional<FovTangents> tangents;
};

// Reversed-Z with an infinite far plane, for glClipControl(GL_LOWER_LEFT,
// GL_ZERO_TO_ONE): depth 1 at the near plane, tending to 0 at infinity.
dmat4 perspective_reversed_z(const Frustum& f);

// The classic OpenGL projection (depth -1..1 from near to far).
dmat4 perspective_standard(const Frustum& f, double far);

// Direction in eye space (not normalised; z = -1) of the ray through the
// centre of pixel (i, j) of a width × height eye image, row 0 at the top.
// Uses width / height as the aspect (f.aspect is not read); with tangents,
// column x of the image is at tangent left + (x / width) · (right - left).
dvec3 pixel_ray_eye(const Frustum& f, int width, int height, int i, int j);

// The same for any point of the image plane in pixel units: x from 0 (left
// edge) to width, y from 0 (top edge) to height. The corner (0, 0) gives
// (-tan(fov/2)·aspect, +tan(fov/2), -1).
dvec3 image_point_ray_eye(const Frustum& f, int width, int height, double x, double y);

}  // namespace impossible::math
