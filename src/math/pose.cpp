// Head pose → eyes → view matrices (see pose.hpp for the conventions).
#include "math/pose.hpp"

#include <algorithm>
#include <cmath>

namespace impossible::math {

glm::dvec2 sin_cos_deg(double deg) {
    // Reduce to [-180, 180] first (fmod is exact), so that multiples of 90°
    // come out exact and large angles keep their precision.
    double r = std::fmod(deg, 360.0);
    if (r > 180.0) r -= 360.0;
    if (r < -180.0) r += 360.0;
    if (r == 0.0) return {0.0, 1.0};
    if (r == 90.0) return {1.0, 0.0};
    if (r == -90.0) return {-1.0, 0.0};
    if (r == 180.0 || r == -180.0) return {0.0, -1.0};
    const double a = radians(r);
    return {std::sin(a), std::cos(a)};
}

dmat3 rotation_x_deg(double deg) {
    const glm::dvec2 sc = sin_cos_deg(deg);
    dmat3 m(1.0);
    m[1] = dvec3(0.0, sc.y, sc.x);
    m[2] = dvec3(0.0, -sc.x, sc.y);
    return m;
}

dmat3 rotation_y_deg(double deg) {
    const glm::dvec2 sc = sin_cos_deg(deg);
    dmat3 m(1.0);
    m[0] = dvec3(sc.y, 0.0, -sc.x);
    m[2] = dvec3(sc.x, 0.0, sc.y);
    return m;
}

dmat3 rotation_z_deg(double deg) {
    const glm::dvec2 sc = sin_cos_deg(deg);
    dmat3 m(1.0);
    m[0] = dvec3(sc.y, sc.x, 0.0);
    m[1] = dvec3(-sc.x, sc.y, 0.0);
    return m;
}

dmat3 head_rotation(const HeadPose& pose) {
    return rotation_y_deg(pose.yaw_deg) * rotation_x_deg(pose.pitch_deg) * rotation_z_deg(-pose.roll_deg);
}

HeadPose head_pose_from(const dvec3& position, const dmat3& r) {
    // R = R_y(yaw) · R_x(pitch) · R_z(-roll): the back column is
    // (sin yaw cos pitch, -sin pitch, cos yaw cos pitch) and the second row is
    // (cos pitch · sin(-roll), cos pitch · cos(-roll), -sin pitch).
    constexpr double deg = 180.0 / kPi;
    HeadPose pose;
    pose.position = position;
    const double sp = std::clamp(-r[2].y, -1.0, 1.0);
    pose.pitch_deg = std::asin(sp) * deg;
    const double cp = std::hypot(r[0].y, r[1].y);
    if (cp > 1e-12) {
        pose.yaw_deg = std::atan2(r[2].x, r[2].z) * deg;
        pose.roll_deg = -std::atan2(r[0].y, r[1].y) * deg;
    } else {  // looking straight up or down: all turning is yaw
        pose.yaw_deg = std::atan2(-r[0].z, r[0].x) * deg;
        pose.roll_deg = 0.0;
    }
    return pose;
}

std::array<Eye, 2> eyes_of(const HeadPose& pose, double ipd) {
    const dmat3 r = head_rotation(pose);
    const dvec3 half = (0.5 * ipd) * r[0];
    return {Eye{pose.position - half, r, pose.position}, Eye{pose.position + half, r, pose.position}};
}

dmat4 view_matrix(const Eye& eye) {
    // The inverse of a rigid transform in its exact form: [Rᵀ | -Rᵀ·p].
    const dmat3 rt = glm::transpose(eye.rotation);
    dmat4 m(rt);
    m[3] = dvec4(-(rt * eye.position), 1.0);
    return m;
}

dmat4 eye_to_world(const Eye& eye) {
    dmat4 m(eye.rotation);
    m[3] = dvec4(eye.position, 1.0);
    return m;
}

Eye transform_eye(const dmat4& m, const Eye& eye) {
    return Eye{dvec3(m * dvec4(eye.position, 1.0)), dmat3(m) * eye.rotation, dvec3(m * dvec4(eye.head, 1.0))};
}

dvec3 forward_of(const dmat3& rotation) { return -rotation[2]; }

}  // namespace impossible::math
