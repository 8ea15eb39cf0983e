// A view's eyes and eye orientations from quaternions (see eyes.hpp).
#include "math/eyes.hpp"

#include <cmath>

#include <glm/geometric.hpp>

namespace impossible::math {

namespace {

// Hamilton's product a ⊗ b of quaternions (x, y, z, w): b's rotation, then a's.
dvec4 multiply(const dvec4& a, const dvec4& b) {
    const dvec3 av(a), bv(b);
    const dvec3 v = a.w * bv + b.w * av + glm::cross(av, bv);
    return {v, a.w * b.w - glm::dot(av, bv)};
}

// The quaternion of a turn of `deg` degrees about unit axis `axis`.
dvec4 axis_quaternion(const dvec3& axis, double deg) {
    const glm::dvec2 sc = sin_cos_deg(0.5 * deg);
    return {sc.x * axis, sc.y};
}

}  // namespace

dmat3 quaternion_rotation(const dvec4& q) {
    const dvec4 u = q / std::sqrt(glm::dot(q, q));
    const double x = u.x, y = u.y, z = u.z, w = u.w;
    dmat3 m;
    m[0] = dvec3(1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y + z * w), 2.0 * (x * z - y * w));
    m[1] = dvec3(2.0 * (x * y - z * w), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z + x * w));
    m[2] = dvec3(2.0 * (x * z + y * w), 2.0 * (y * z - x * w), 1.0 - 2.0 * (x * x + y * y));
    return m;
}

dvec4 angles_quaternion(const HeadPose& angles) {
    const dvec4 yaw = axis_quaternion(dvec3(0.0, 1.0, 0.0), angles.yaw_deg);
    const dvec4 pitch = axis_quaternion(dvec3(1.0, 0.0, 0.0), angles.pitch_deg);
    const dvec4 roll = axis_quaternion(dvec3(0.0, 0.0, 1.0), -angles.roll_deg);
    return multiply(multiply(yaw, pitch), roll);
}

EyeOffset eye_offset(const QuaternionPose& pose) { return {pose.position, quaternion_rotation(pose.orientation)}; }

EyeOffset eye_offset(const HeadPose& pose) { return {pose.position, quaternion_rotation(angles_quaternion(pose))}; }

std::array<Eye, 2> eyes_of(const HeadPose& head, const std::array<EyeOffset, 2>& offsets) {
    const dmat3 r = head_rotation(head);
    std::array<Eye, 2> eyes;
    for (std::size_t e = 0; e < 2; ++e)
        eyes[e] = Eye{head.position + r * offsets[e].position, r * offsets[e].rotation, head.position};
    return eyes;
}

std::array<Eye, 2> eyes_of(const View& view, const HeadPose& head) {
    return view.eye_offsets ? eyes_of(head, *view.eye_offsets) : eyes_of(head, view.ipd);
}

std::array<Eye, 2> eyes_of(const View& view) { return eyes_of(view, view.head); }

}  // namespace impossible::math
