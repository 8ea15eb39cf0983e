// A view as a front end asks for it, resolved against the layout by the one
// rule every front end shares, and checked against the named limits
// (math/view_limits.hpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "layout/layout.hpp"
#include "math/pose.hpp"
#include "math/view.hpp"
#include "session/field_error.hpp"

namespace impossible::session {

// Where the head is, as asked: a pose (none: the layout's start) and the id
// of its room (none: see place_head).
struct HeadRequest {
    std::optional<math::HeadPose> pose;
    std::optional<std::string> room;
};

// The rooms whose box or prism holds `head` (layout::room_contains, edges
// included), in file order.
std::vector<int> rooms_holding(const layout::Layout& layout, const math::dvec3& head);

// Sets view.head and view.room: without a pose the layout's start (in the
// named room, else the start room); with a pose, the named room, else the
// one room holding the head. A room that does not exist, or a pose in no
// room or in several with no room named, is a FieldError.
std::optional<FieldError> place_head(const layout::Layout& layout, const HeadRequest& request, math::View& view);

// The first setting of `view` outside its limits (math/view_limits.hpp):
// sizes, IPD, field of view, depths, the budget, light depth, finite time
// and poses, each eye's optics and pose relative to the head
// (docs/headsets.md's rules).
std::optional<FieldError> view_problem(const math::View& view);

// What the library and Python do with a view: the head as asked, its limits
// checked (view_problem), then placed (place_head).
std::optional<FieldError> resolve_view(const layout::Layout& layout, const HeadRequest& request, math::View& view);

}  // namespace impossible::session
