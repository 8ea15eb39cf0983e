#include "session/view_request.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "base/format.hpp"
#include "layout/hmd_profile.hpp"
#include "layout/room_shape.hpp"
#include "math/view_limits.hpp"

namespace impossible::session {

namespace lim = math::limits;

std::vector<int> rooms_holding(const layout::Layout& layout, const math::dvec3& p) {
    std::vector<int> holding;
    for (std::size_t i = 0; i < layout.rooms.size(); ++i) {
        // Its box, or its prism (layout-format.md, "Rooms of any shape").
        if (layout::room_contains(layout.rooms[i], p)) holding.push_back(static_cast<int>(i));
    }
    return holding;
}

std::optional<FieldError> place_head(const layout::Layout& layout, const HeadRequest& request, math::View& view) {
    using Kind = FieldError::Kind;
    if (request.pose) {
        view.head = *request.pose;
    } else {
        view.head = {};
        view.head.position = layout.start.position;
        view.head.yaw_deg = layout.start.yaw_deg;
    }
    if (request.room) {
        view.room = layout::find_room(layout, *request.room);
        if (view.room < 0)
            return FieldError{Kind::Problem, "room", "there is no room '" + *request.room + "' in " + layout.source};
        return {};
    }
    if (!request.pose) {
        view.room = layout.start.room;
        return {};
    }
    const std::vector<int> holding = rooms_holding(layout, view.head.position);
    if (holding.size() == 1) {
        view.room = holding[0];
        return {};
    }
    std::string names;
    for (int i : holding) names += (names.empty() ? "" : ", ") + layout.rooms[i].id;
    return FieldError{Kind::Problem, "pose",
                      holding.empty() ? "the head is in no room; give {room}"
                                      : "the head is in several rooms (" + names + "); give {room}"};
}

namespace {

bool finite_pose(const math::HeadPose& p) {
    for (double v : {p.position.x, p.position.y, p.position.z, p.yaw_deg, p.pitch_deg, p.roll_deg})
        if (!std::isfinite(v)) return false;
    return true;
}

// What is wrong with one eye's optics (the profile's rules,
// docs/headsets.md), or "".
std::string optics_problem(const math::EyeOptics& eye, const char* name) {
    const std::string at = std::string(name) + " eye: ";
    if (const std::optional<std::string> problem = layout::fov_angles_problem(eye.fov)) return at + "fov: " + *problem;
    const std::size_t corners = eye.visible_area.size();
    if (corners == 0) return {};
    if (corners < 3 || corners > layout::kMaxVisibleAreaCorners)
        return at + "visible_area has " + std::to_string(corners) + " corners, not 3.." +
               std::to_string(layout::kMaxVisibleAreaCorners);
    for (std::size_t k = 0; k < corners; ++k)
        for (double c : {eye.visible_area[k].x, eye.visible_area[k].y})
            if (!(c >= 0.0 && c <= 1.0)) return at + "visible_area[" + std::to_string(k) + "] is not within 0..1";
    if (const std::optional<math::PolygonProblem> problem = math::simple_polygon_problem(eye.visible_area))
        return at + "visible_area[" + std::to_string(problem->corner) +
               "]: the visible area must be a simple polygon: " + problem->message;
    return {};
}

// What is wrong with one eye's pose relative to the head, or "": a finite
// position at most kMaxEyeDistance from the head centre, and a rotation
// (orthonormal within 1e-9, determinant +1).
std::string eye_offset_problem(const math::EyeOffset& eye, const char* name) {
    const std::string at = "{eye_poses}: " + std::string(name) + " eye: ";
    const double distance = glm::length(eye.position);
    if (!std::isfinite(distance)) return at + "the position holds a number that is not finite";
    if (!(distance <= lim::kMaxEyeDistance))
        return at + "the position is " + format_number(distance) + " m from the head centre, more than " +
               format_number(lim::kMaxEyeDistance) + " m";
    const math::dmat3 gram = glm::transpose(eye.rotation) * eye.rotation;
    double error = std::abs(glm::determinant(eye.rotation) - 1.0);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) error = std::max(error, std::abs(gram[c][r] - (c == r ? 1.0 : 0.0)));
    if (!(error <= 1e-9)) return at + "the orientation is not a rotation";
    return {};
}

std::optional<FieldError> value_error(const std::string& field, const std::string& message) {
    return FieldError{FieldError::Kind::Value, field, message};
}

std::optional<FieldError> number_problem(const math::View& v) {
    if (!lim::kEyeSide.contains(v.eye_width) || !lim::kEyeSide.contains(v.eye_height))
        return value_error("size", std::to_string(v.eye_width) + "x" + std::to_string(v.eye_height) +
                                       " is not within " + lim::range_text(lim::kEyeSide) + " pixels");
    if (!lim::kIpd.contains(v.ipd))
        return value_error("ipd", format_number(v.ipd) + " is not in " + lim::range_text(lim::kIpd) + " m");
    if (!(v.fov_y_deg >= lim::kMinFovDeg && v.fov_y_deg < lim::kMaxFovDeg))
        return value_error("fov", format_number(v.fov_y_deg) + " is not in " + format_number(lim::kMinFovDeg) + ".." +
                                      format_number(lim::kMaxFovDeg) + " degrees");
    if (!lim::kMaxDepth.contains(v.max_depth))
        return value_error("max_depth", std::to_string(v.max_depth) + " is not in " + lim::range_text(lim::kMaxDepth));
    if (!lim::kPortalPasses.contains(v.max_portal_passes))
        return value_error("max_portal_passes",
                           std::to_string(v.max_portal_passes) + " is not in " + lim::range_text(lim::kPortalPasses));
    if (v.light_depth && !lim::kLightDepth.contains(*v.light_depth))
        return value_error("light_depth",
                           std::to_string(*v.light_depth) + " is not in " + lim::range_text(lim::kLightDepth));
    if (v.exposure && !lim::kExposure.contains(*v.exposure))
        return value_error("exposure", format_number(*v.exposure) + " is not in " + lim::range_text(lim::kExposure));
    if (!std::isfinite(v.time)) return value_error("time", "is not a finite number");
    return {};
}

}  // namespace

std::optional<FieldError> view_problem(const math::View& v) {
    if (std::optional<FieldError> problem = number_problem(v)) return problem;
    using Kind = FieldError::Kind;
    if (!finite_pose(v.head)) return FieldError{Kind::Problem, "pose", "the pose holds a number that is not finite"};
    if (v.hands && !(finite_pose((*v.hands)[0]) && finite_pose((*v.hands)[1])))
        return FieldError{Kind::Problem, "hands", "the hands hold a number that is not finite"};
    if (v.eye_optics)
        for (std::size_t e = 0; e < 2; ++e)
            if (std::string problem = optics_problem((*v.eye_optics)[e], e == 0 ? "left" : "right"); !problem.empty())
                return FieldError{Kind::Problem, "eye_optics", problem};
    if (v.eye_offsets)
        for (std::size_t e = 0; e < 2; ++e)
            if (std::string problem = eye_offset_problem((*v.eye_offsets)[e], e == 0 ? "left" : "right");
                !problem.empty())
                return FieldError{Kind::Problem, "eye_poses", problem};
    return {};
}

std::optional<FieldError> resolve_view(const layout::Layout& layout, const HeadRequest& request, math::View& view) {
    view.head = request.pose.value_or(math::HeadPose{});
    if (std::optional<FieldError> problem = view_problem(view)) return problem;
    return place_head(layout, request, view);
}

}  // namespace impossible::session
