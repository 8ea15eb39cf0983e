// A public View checked and resolved into the library's math::View, with the
// CLI's ranges and the CLI's rule for the head's room.
#include <cmath>

#include "api/api_data.hpp"
#include "base/format.hpp"
#include "layout/hmd_profile.hpp"
#include "layout/room_shape.hpp"
#include "math/polygon.hpp"

namespace impossible::api {

namespace {

bool finite_pose(const Pose& p) {
    for (double v : {p.x, p.y, p.z, p.yaw, p.pitch, p.roll})
        if (!std::isfinite(v)) return false;
    return true;
}

// What is wrong with one eye's optics (the profile's rules,
// docs/headsets.md), or nothing.
std::string optics_problem(const EyeOptics& eye, const char* name) {
    const std::string at = std::string(name) + " eye: ";
    if (const std::optional<std::string> problem = layout::fov_angles_problem(to_fov(eye.fov)))
        return at + "fov: " + *problem;
    const std::size_t corners = eye.visible_area.size();
    if (corners == 0) return {};
    if (corners < 3 || corners > layout::kMaxVisibleAreaCorners)
        return at + "visible_area has " + std::to_string(corners) + " corners, not 3.." +
               std::to_string(layout::kMaxVisibleAreaCorners);
    for (std::size_t k = 0; k < corners; ++k)
        for (double c : eye.visible_area[k])
            if (!(c >= 0.0 && c <= 1.0)) return at + "visible_area[" + std::to_string(k) + "] is not within 0..1";
    if (const std::optional<math::PolygonProblem> problem = math::simple_polygon_problem(to_polygon(eye.visible_area)))
        return at + "visible_area[" + std::to_string(problem->corner) +
               "]: the visible area must be a simple polygon: " + problem->message;
    return {};
}

// The ranges of the view options (docs/cli.md).
std::string range_problem(const View& v) {
    if (v.width < 1 || v.width > 8192 || v.height < 1 || v.height > 8192)
        return "size " + std::to_string(v.width) + "x" + std::to_string(v.height) + " is not within 1..8192 pixels";
    if (!(v.ipd >= 0 && v.ipd <= 10)) return "ipd " + format_number(v.ipd) + " is not in 0..10 m";
    if (!(v.fov_deg >= 1 && v.fov_deg < 179)) return "fov " + format_number(v.fov_deg) + " is not in 1..179 degrees";
    if (v.max_depth < 0 || v.max_depth > 250) return "max_depth " + std::to_string(v.max_depth) + " is not in 0..250";
    if (v.samples != 1 && v.samples != 2 && v.samples != 4 && v.samples != 8 && v.samples != 16)
        return "samples " + std::to_string(v.samples) + " is not 1, 2, 4, 8 or 16";
    if (v.max_portal_passes < 0 || v.max_portal_passes > 10'000'000)
        return "max_portal_passes " + std::to_string(v.max_portal_passes) + " is not in 0..10000000";
    if (v.light_depth && (*v.light_depth < 0 || *v.light_depth > layout::kMaxLightDepth))
        return "light_depth " + std::to_string(*v.light_depth) + " is not in 0.." +
               std::to_string(layout::kMaxLightDepth);
    if (!std::isfinite(v.time)) return "time is not a finite number";
    if (v.pose && !finite_pose(*v.pose)) return "the pose holds a number that is not finite";
    if (v.hands && !(finite_pose((*v.hands)[0]) && finite_pose((*v.hands)[1])))
        return "the hands hold a number that is not finite";
    if (v.eye_optics)
        for (std::size_t e = 0; e < 2; ++e)
            if (std::string problem = optics_problem((*v.eye_optics)[e], e == 0 ? "left" : "right"); !problem.empty())
                return problem;
    return {};
}

}  // namespace

std::vector<int> rooms_holding(const layout::Layout& layout, const math::dvec3& p) {
    std::vector<int> holding;
    for (std::size_t i = 0; i < layout.rooms.size(); ++i) {
        // Its box, or its prism (layout-format.md, "Rooms of any shape").
        if (layout::room_contains(layout.rooms[i], p)) holding.push_back(static_cast<int>(i));
    }
    return holding;
}

Result<math::View> resolve_view(const layout::Layout& layout, const View& view) {
    if (const std::string problem = range_problem(view); !problem.empty()) return impossible::Error{problem};
    math::View v;
    v.ipd = view.ipd;
    v.fov_y_deg = view.fov_deg;
    v.eye_width = view.width;
    v.eye_height = view.height;
    v.max_depth = view.max_depth;
    v.time = view.time;
    v.light_depth = view.light_depth;
    if (view.eye_optics) {
        std::array<math::EyeOptics, 2> eyes;
        for (std::size_t e = 0; e < 2; ++e)
            eyes[e] = {to_fov((*view.eye_optics)[e].fov), to_polygon((*view.eye_optics)[e].visible_area)};
        v.eye_optics = eyes;
    }
    if (view.hands)
        v.hands = std::array<math::HeadPose, 2>{to_head_pose((*view.hands)[0]), to_head_pose((*view.hands)[1])};
    if (view.pose) {
        v.head = to_head_pose(*view.pose);
    } else {
        v.head.position = layout.start.position;
        v.head.yaw_deg = layout.start.yaw_deg;
    }
    if (!view.room.empty()) {
        v.room = layout::find_room(layout, view.room);
        if (v.room < 0) return impossible::Error{"there is no room '" + view.room + "' in " + layout.source};
    } else if (!view.pose) {
        v.room = layout.start.room;
    } else {
        const std::vector<int> holding = rooms_holding(layout, v.head.position);
        if (holding.size() != 1) {
            std::string names;
            for (int i : holding) names += (names.empty() ? "" : ", ") + layout.rooms[i].id;
            return impossible::Error{holding.empty() ? "the head is in no room; give the room"
                                                     : "the head is in several rooms (" + names + "); give the room"};
        }
        v.room = holding[0];
    }
    return v;
}

}  // namespace impossible::api
