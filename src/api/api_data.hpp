// What the public API's handles hold (include/impossible/impossible.hpp), and
// the conversions between its plain types and the library's own.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "base/result.hpp"
#include "impossible/impossible.hpp"
#include "layout/layout.hpp"
#include "math/eyes.hpp"
#include "math/pose.hpp"
#include "math/view.hpp"
#include "render/frame.hpp"
#include "session/session.hpp"

namespace impossible::api {

// The session (the layout and its links, linked once) that every renderer,
// tracer and walker made from one api::Layout shares.
struct LayoutData {
    explicit LayoutData(layout::Layout l) : session(std::move(l)) {}
    explicit LayoutData(session::Session s) : session(std::move(s)) {}
    session::Session session;
    const layout::Layout& layout = session.layout();
    std::vector<layout::Diagnostic> warnings;  // the loader's
    std::vector<std::string> warning_lines;    // the same as "FILE:LINE:COLUMN: message"
};

// The layout of `paired`, a session of `loaded`'s layout with another
// pairing (session::WalkDriver::session, session::replay_to): `loaded`
// itself when it is that session, else a Layout sharing its data, with
// `loaded`'s warnings.
inline Layout paired_layout_of(const Layout& loaded, const session::Session& paired) {
    if (&paired.layout() == &loaded.data().layout) return loaded;
    auto data = std::make_shared<LayoutData>(paired);
    data->warnings = loaded.data().warnings;
    data->warning_lines = loaded.data().warning_lines;
    return Layout::of(std::move(data));
}

inline math::HeadPose to_head_pose(const Pose& p) { return {{p.x, p.y, p.z}, p.yaw, p.pitch, p.roll}; }
inline Pose to_pose(const math::HeadPose& h) {
    return {h.position.x, h.position.y, h.position.z, h.yaw_deg, h.pitch_deg, h.roll_deg};
}

inline math::QuaternionPose to_quaternion_pose(const EyePose& e) {
    return {{e.position[0], e.position[1], e.position[2]},
            {e.orientation[0], e.orientation[1], e.orientation[2], e.orientation[3]}};
}
inline EyePose to_eye_pose(const math::QuaternionPose& q) {
    return {{q.position.x, q.position.y, q.position.z},
            {q.orientation.x, q.orientation.y, q.orientation.z, q.orientation.w}};
}

inline math::FovAngles to_fov(const FovAngles& f) { return {f.left, f.right, f.up, f.down}; }
inline math::Polygon2 to_polygon(const std::vector<std::array<double, 2>>& corners) {
    math::Polygon2 poly;
    poly.reserve(corners.size());
    for (const std::array<double, 2>& c : corners) poly.emplace_back(c[0], c[1]);
    return poly;
}

// The view as the renderer and tracer take it: the head and its room
// resolved by the session's one rule (a pose in no room or in several needs
// a room), sizes and numbers checked against the named limits
// (session/view_request.hpp), errors naming the View's fields.
Result<math::View> resolve_view(const layout::Layout& layout, const View& view);

// The rasteriser's frame: the resolved view, the samples and the options
// (RenderOptions' ranges checked, errors naming its fields).
Result<render::FrameDesc> frame_desc(const layout::Layout& layout, const View& view, const RenderOptions& options);

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
