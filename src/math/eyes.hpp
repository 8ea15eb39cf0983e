// A view's eyes: each placed by its pose relative to the head
// (View::eye_offsets: a headset's per-eye poses, canted displays included),
// or at ±ipd/2 along the head's x axis looking the head's way. Every
// consumer of a View (rasteriser, tracer, preview, walker) places its eyes
// here, so they all see the same eyes. Also the quaternions headsets give
// an eye's orientation in (OpenXR's XrQuaternionf, WebXR's orientation).
#pragma once

#include <array>

#include "math/pose.hpp"
#include "math/view.hpp"

namespace impossible::math {

// How far the length of a quaternion given as a unit one may be from 1.
inline constexpr double kUnitQuaternionTolerance = 1e-6;

// An eye's pose as a headset gives it, relative to the head: a position
// (metres) and an orientation, a unit quaternion (x, y, z, w).
struct QuaternionPose {
    dvec3 position{0.0};
    dvec4 orientation{0.0, 0.0, 0.0, 1.0};
};

// The rotation of quaternion q = (x, y, z, w), normalised first; (0, 0, 0, 1)
// gives the identity exactly.
dmat3 quaternion_rotation(const dvec4& q);
// The unit quaternion of a pose's yaw, pitch and roll (head_rotation's
// convention: R_y(yaw) · R_x(pitch) · R_z(-roll)); its position is not read.
dvec4 angles_quaternion(const HeadPose& angles);
// The offset of a quaternion pose (its rotation by quaternion_rotation).
EyeOffset eye_offset(const QuaternionPose& pose);
// The offset of a pose in head coordinates, as --eye-poses gives it
// (position, yaw, pitch, roll), through angles_quaternion, so that the
// command line, the library and Python turn the same angles into the same
// rotation.
EyeOffset eye_offset(const HeadPose& pose);

// Eyes at `head`, left first: eye k at head + R · offset.position with axes
// R · offset.rotation (R = head_rotation(head)), Eye::head the head centre.
std::array<Eye, 2> eyes_of(const HeadPose& head, const std::array<EyeOffset, 2>& offsets);
// The view's eyes at `head` (e.g. the preview's physical head): by
// view.eye_offsets, or eyes_of(head, view.ipd) exactly (bit for bit).
std::array<Eye, 2> eyes_of(const View& view, const HeadPose& head);
// The view's eyes at view.head.
std::array<Eye, 2> eyes_of(const View& view);

}  // namespace impossible::math
