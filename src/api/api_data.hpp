// What the public API's handles hold (include/impossible/impossible.hpp), and
// the conversions between its plain types and the library's own.
#pragma once

#include <string>
#include <vector>

#include "base/result.hpp"
#include "impossible/impossible.hpp"
#include "layout/layout.hpp"
#include "math/pose.hpp"
#include "math/view.hpp"

namespace impossible::api {

struct LayoutData {
    layout::Layout layout;
    std::vector<layout::Diagnostic> warnings;  // the loader's
    std::vector<std::string> warning_lines;    // the same as "FILE:LINE:COLUMN: message"
};

inline math::HeadPose to_head_pose(const Pose& p) { return {{p.x, p.y, p.z}, p.yaw, p.pitch, p.roll}; }
inline Pose to_pose(const math::HeadPose& h) {
    return {h.position.x, h.position.y, h.position.z, h.yaw_deg, h.pitch_deg, h.roll_deg};
}

inline math::FovAngles to_fov(const FovAngles& f) { return {f.left, f.right, f.up, f.down}; }
inline math::Polygon2 to_polygon(const std::vector<std::array<double, 2>>& corners) {
    math::Polygon2 poly;
    poly.reserve(corners.size());
    for (const std::array<double, 2>& c : corners) poly.emplace_back(c[0], c[1]);
    return poly;
}

// The view as the renderer and tracer take it: the head and its room
// resolved as `render` does (a pose in no room or in several needs a room),
// sizes and numbers checked as the CLI checks them.
Result<math::View> resolve_view(const layout::Layout& layout, const View& view);

// The rooms whose box or prism holds the head (layout::room_contains, edges
// included), in file order: a view given only a pose is in the one room
// holding it (the API's and the commands' rule).
std::vector<int> rooms_holding(const layout::Layout& layout, const math::dvec3& head);

// Runs `body`, turning any exception (memory, a library's) into an Error:
// nothing throws across the API.
template <class F>
auto no_throw(F&& body) -> decltype(body()) {
    try {
        return body();
    } catch (const std::exception& e) {
        return Error{std::string("internal error: ") + e.what()};
    } catch (...) {
        return Error{"internal error"};
    }
}

// The library's Result as the API's Expected.
template <class T>
Expected<T> expected(Result<T>&& r) {
    if (!r) return Error{r.error()};
    return std::move(*r);
}

}  // namespace impossible::api
