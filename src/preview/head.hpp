// The physical head of the preview: keyboard and mouse move it as a person in
// a headset moves, inside the play area; the walker maps it to the layout.
// Pure math, no GL and no window.
#pragma once

#include <array>
#include <optional>

#include "layout/layout.hpp"
#include "math/pose.hpp"

namespace impossible::preview {

// What the user did during one frame.
struct MoveInput {
    double dt = 0.0;                     // seconds since the last frame
    int forward = 0, right = 0, up = 0;  // -1, 0 or +1 each
    bool fast = false;
    double mouse_dx = 0.0, mouse_dy = 0.0;  // pixels, +x right, +y down
};

inline constexpr double kWalkSpeed = 1.4;  // m/s
inline constexpr double kFastFactor = 3.0;
inline constexpr double kClimbSpeed = 0.8;  // m/s, Q / E
inline constexpr double kMouseDegPerPixel = 0.12;
inline constexpr double kMaxPitch = 89.0;
inline constexpr double kMinHeight = 0.2, kMaxHeight = 3.0;

// Turns the head by the mouse (yaw and pitch; roll is kept) and moves it in
// the horizontal plane along its yaw. A head inside the play area stays
// inside it: a step never takes it further beyond an edge than it was.
math::HeadPose move_head(const math::HeadPose& head, const MoveInput& input,
                         const std::optional<layout::PlayArea>& play_area);

// The hand the preview holds out (G): the right hand `distance` metres in
// front of the head (kMinHandDistance..kMaxHandDistance, `,` and `.` step
// it), kHandOffset right of and below the view's centre, turned as the
// head; the left hand hangs at the side, 0.2 m left of, 0.1 m in front of
// and 0.7 m below the head, turned by the head's yaw alone. Physical poses,
// left first, as a path file's line holds them.
inline constexpr double kHandDistance = 0.4, kMinHandDistance = 0.1, kMaxHandDistance = 1.0, kHandStep = 0.05;
inline constexpr double kHandOffset = 0.12;
std::array<math::HeadPose, 2> held_hands(const math::HeadPose& head, double distance);

// Distances from the head to the play area's edges -x, +x, -z, +z (negative
// outside); nothing without a play area.
std::optional<std::array<double, 4>> edge_distances(const math::dvec3& physical_head,
                                                    const std::optional<layout::PlayArea>& play_area);

}  // namespace impossible::preview
