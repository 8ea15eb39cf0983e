// Headset profiles (`--hmd FILE.json`, docs/headsets.md): each eye's field
// of view (OpenXR's XrFovf angles, degrees), its image size and the visible
// area of its image (the rest is the hidden area the lenses never show), and
// the IPD, or each eye's pose relative to the head. Errors are one line, FILE:LINE:COLUMN: field: message, as the
// layout loader's (unknown fields refused, names starting with _ are
// comments).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "base/result.hpp"
#include "math/eyes.hpp"
#include "math/view.hpp"

namespace impossible::layout {

struct HmdProfile {
    std::string name;
    std::string source;                   // where the numbers come from
    double ipd = 0.064;                   // not read with eye_poses
    int eye_width = 0, eye_height = 0;    // the same for both eyes
    std::array<math::EyeOptics, 2> eyes;  // left, right
    // Each eye's "position" and "orientation" (a unit quaternion x, y, z, w)
    // relative to the head, left then right, as given; none: the IPD rule.
    std::optional<std::array<math::QuaternionPose, 2>> eye_poses;
};

// Angles of one eye's field of view: each within ±kMaxFovAngleDeg, right at
// least kMinFovExtentDeg right of left and up as far above down.
inline constexpr double kMaxFovAngleDeg = 89.5;
inline constexpr double kMinFovExtentDeg = 1.0;
// A visible area or a visibility mask's line loop has 3..kMaxVisibleAreaCorners
// corners (the visible area also once clipped to the image); a mask's
// triangles at most kMaxVisibilityMaskIndices vertices and indices.
inline constexpr std::size_t kMaxVisibleAreaCorners = 4096;
inline constexpr std::size_t kMaxVisibilityMaskIndices = 3 * 4096;
inline constexpr std::size_t kMaxHmdProfileBytes = 1u << 20;

// What is wrong with the angles, or nothing.
std::optional<std::string> fov_angles_problem(const math::FovAngles& fov);

Result<HmdProfile> parse_hmd_profile(std::string_view text, const std::string& file);
Result<HmdProfile> read_hmd_profile_file(const std::string& path);

}  // namespace impossible::layout
