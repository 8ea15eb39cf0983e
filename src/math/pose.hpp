// Head pose → eyes → view matrices (layout-format.md, "Head, eyes and walking").
//
// Orientation: yaw about +Y, then pitch about the head's right axis, then roll
// about its forward axis: R = R_y(yaw) · R_x(pitch) · R_z(-roll). Positive yaw
// turns left, positive pitch looks up, positive roll is right-handed about the
// forward axis (-Z), which lowers the right eye.
//
// Angles are degrees. Rotations are built from sin_cos_deg, which is exact at
// multiples of 90° (yaw 90 looks exactly along -X), so axis-aligned poses
// carry no rounding noise.
#pragma once

#include <array>

#include <glm/vec2.hpp>

#include "math/conventions.hpp"

namespace impossible::math {

struct HeadPose {
    dvec3 position{0.0};  // head centre
    double yaw_deg = 0.0;
    double pitch_deg = 0.0;
    double roll_deg = 0.0;
};

// A camera: position and orientation whose columns are right, up, back
// (forward = -column 2).
// `head` is the head centre the eye belongs to, in the same coordinates:
// carried with the eye through portals and mirrors, it decides whether the
// eye has a door box's inner faces (math/crossing.hpp, has_inner_faces).
struct Eye {
    dvec3 position{0.0};
    dmat3 rotation{1.0};
    dvec3 head{0.0};
};

// An eye's pose relative to the head, as a headset gives it (WebXR's
// XRView.transform relative to the viewer, OpenXR's XrView.pose relative to
// the view space; math/eyes.hpp places eyes by it).
struct EyeOffset {        // an eye's pose in the head's coordinates (x right, y up, z back)
    dvec3 position{0.0};  // metres from the head centre
    dmat3 rotation{1.0};  // the eye's axes (columns right, up, back) in head coordinates
    bool operator==(const EyeOffset&) const = default;
};

// (sin, cos) of an angle in degrees: reduced to [-180°, 180°] first, exact at
// multiples of 90°.
glm::dvec2 sin_cos_deg(double deg);

// Right-handed rotations about the axes (positive angles counter-clockwise
// seen from the positive axis). rotation_y_deg(90) maps -Z onto -X.
dmat3 rotation_x_deg(double deg);
dmat3 rotation_y_deg(double deg);
dmat3 rotation_z_deg(double deg);

// R = R_y(yaw) · R_x(pitch) · R_z(-roll); columns right, up, back.
dmat3 head_rotation(const HeadPose& pose);

// The inverse of head_rotation: yaw, pitch and roll of a head rotation, at
// `position`. Looking straight up or down (pitch ±90°), yaw and roll turn the
// same way; all of it is given to yaw (roll 0).
HeadPose head_pose_from(const dvec3& position, const dmat3& rotation);

// The left eye first, at head - ipd/2 · right; the right at head + ipd/2 · right,
// both looking the head's way (a View's eyes: math/eyes.hpp).
std::array<Eye, 2> eyes_of(const HeadPose& pose, double ipd);

// World → eye space (inverse of the eye's rigid transform).
dmat4 view_matrix(const Eye& eye);

// Eye → world (the eye's rigid transform).
dmat4 eye_to_world(const Eye& eye);

// The same eye seen through a rigid transform M (e.g. a portal's transfer
// matrix): position, axes and head centre mapped by M.
Eye transform_eye(const dmat4& m, const Eye& eye);

// Forward view direction of a rotation (-column 2).
dvec3 forward_of(const dmat3& rotation);

}  // namespace impossible::math
