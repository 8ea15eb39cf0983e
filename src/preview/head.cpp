#include "preview/head.hpp"

#include <algorithm>
#include <cmath>

#include "math/polygon.hpp"

namespace impossible::preview {

math::HeadPose move_head(const math::HeadPose& head, const MoveInput& in, const std::optional<layout::PlayArea>& area) {
    math::HeadPose out = head;
    out.yaw_deg = std::remainder(head.yaw_deg - in.mouse_dx * kMouseDegPerPixel, 360.0);
    out.pitch_deg = std::clamp(head.pitch_deg - in.mouse_dy * kMouseDegPerPixel, -kMaxPitch, kMaxPitch);

    const glm::dvec2 sc = math::sin_cos_deg(out.yaw_deg);
    const math::dvec3 forward{-sc.x, 0.0, -sc.y};  // yaw 0 looks along -Z, yaw 90 along -X
    const math::dvec3 right{sc.y, 0.0, -sc.x};
    const double speed = kWalkSpeed * (in.fast ? kFastFactor : 1.0);
    out.position += (forward * double(in.forward) + right * double(in.right)) * (speed * in.dt);
    out.position.y += double(in.up) * kClimbSpeed * (in.fast ? kFastFactor : 1.0) * in.dt;
    out.position.y =
        std::clamp(out.position.y, std::min(kMinHeight, head.position.y), std::max(kMaxHeight, head.position.y));
    if (area) {
        out.position.x =
            std::clamp(out.position.x, std::min(area->min.x, head.position.x), std::max(area->max.x, head.position.x));
        out.position.z =
            std::clamp(out.position.z, std::min(area->min.y, head.position.z), std::max(area->max.y, head.position.z));
        // A polygon: a step that would leave it is not taken.
        if (!area->polygon.empty() && !math::contains(area->polygon, {out.position.x, out.position.z}) &&
            math::contains(area->polygon, {head.position.x, head.position.z})) {
            out.position.x = head.position.x;
            out.position.z = head.position.z;
        }
    }
    return out;
}

std::array<math::HeadPose, 2> held_hands(const math::HeadPose& head, double distance) {
    math::HeadPose left;
    left.yaw_deg = head.yaw_deg;
    left.position = head.position + math::rotation_y_deg(head.yaw_deg) * math::dvec3{-0.2, -0.7, -0.1};
    math::HeadPose right = head;
    right.position = head.position + math::head_rotation(head) * math::dvec3{kHandOffset, -kHandOffset, -distance};
    return {left, right};
}

std::optional<std::array<double, 4>> edge_distances(const math::dvec3& p, const std::optional<layout::PlayArea>& area) {
    if (!area) return std::nullopt;
    return std::array<double, 4>{p.x - area->min.x, area->max.x - p.x, p.z - area->min.y, area->max.y - p.z};
}

}  // namespace impossible::preview
