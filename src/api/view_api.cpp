// A public View (and RenderOptions) checked and resolved into the library's
// own, through the session's one rule and named limits.
#include <cmath>

#include "api/api_data.hpp"
#include "base/format.hpp"
#include "math/view_limits.hpp"
#include "session/view_request.hpp"

namespace impossible::api {

namespace {

namespace lim = math::limits;

math::View view_of(const View& view) {
    math::View v;
    v.ipd = view.ipd;
    v.fov_y_deg = view.fov_deg;
    v.eye_width = view.width;
    v.eye_height = view.height;
    v.max_depth = view.max_depth;
    v.max_portal_passes = view.max_portal_passes;
    v.time = view.time;
    v.light_depth = view.light_depth;
    v.exposure = view.exposure;
    if (view.eye_optics) {
        std::array<math::EyeOptics, 2> eyes;
        for (std::size_t e = 0; e < 2; ++e)
            eyes[e] = {to_fov((*view.eye_optics)[e].fov), to_polygon((*view.eye_optics)[e].visible_area)};
        v.eye_optics = eyes;
    }
    if (view.eye_poses)
        v.eye_offsets = std::array<math::EyeOffset, 2>{math::eye_offset(to_quaternion_pose((*view.eye_poses)[0])),
                                                       math::eye_offset(to_quaternion_pose((*view.eye_poses)[1]))};
    if (view.hands)
        v.hands = std::array<math::HeadPose, 2>{to_head_pose((*view.hands)[0]), to_head_pose((*view.hands)[1])};
    return v;
}

// An orientation that is not a unit quaternion (within
// math::kUnitQuaternionTolerance), as a profile's is refused.
std::optional<std::string> eye_poses_problem(const View& view) {
    if (!view.eye_poses) return {};
    for (std::size_t e = 0; e < 2; ++e) {
        const std::array<double, 4>& q = (*view.eye_poses)[e].orientation;
        const double length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        if (!(std::abs(length - 1.0) <= math::kUnitQuaternionTolerance))
            return std::string("eye_poses: ") + (e == 0 ? "left" : "right") +
                   " eye: the orientation is not a unit quaternion (x, y, z, w): its length is " +
                   format_number(length) + ", not 1 within 1e-6";
    }
    return {};
}

std::optional<std::string> options_problem(const RenderOptions& o) {
    if (!(o.texture_scale > 0.0 && o.texture_scale <= lim::kMaxPortalTextureScale))
        return "texture_scale " + format_number(o.texture_scale) + " is not in (0, " +
               format_number(lim::kMaxPortalTextureScale) + "]";
    if (!lim::kMaxDepth.contains(o.texture_from_level))
        return "texture_from_level " + std::to_string(o.texture_from_level) + " is not in " +
               lim::range_text(lim::kMaxDepth);
    if (!lim::kShadowMapSize.contains(o.shadow_size))
        return "shadow_size " + std::to_string(o.shadow_size) + " is not in " + lim::range_text(lim::kShadowMapSize);
    return {};
}

render::Technique technique_of(const View& view, const RenderOptions& o) {
    render::Technique t;
    t.stereo = o.stereo == Stereo::ViewportIndex ? render::StereoMode::ViewportIndex
               : o.stereo == Stereo::TwoPass     ? render::StereoMode::TwoPass
                                                 : render::StereoMode::ClipShift;
    t.clip = o.clip == Clip::Oblique ? render::ClipMode::Oblique : render::ClipMode::ClipDistance;
    t.depth = o.depth == Depth::Standard ? render::DepthMode::Standard : render::DepthMode::ReversedZ;
    t.samples = view.samples;
    // As `render --technique` (cli/technique_options.cpp): hybrid draws
    // textures of the scale from its level on; the others none.
    if (o.technique == Technique::Hybrid) {
        t.portal_texture_scale = o.texture_scale;
        t.portal_texture_level = o.texture_from_level;
    }
    t.z_clear = o.technique == Technique::ZClear;
    t.occlusion_test = o.occlusion_test;
    t.shadows = o.shadows;
    t.shadow_map_size = o.shadow_size;
    return t;
}

}  // namespace

Result<math::View> resolve_view(const layout::Layout& layout, const View& view) {
    if (const std::optional<std::string> problem = eye_poses_problem(view)) return impossible::Error{*problem};
    math::View v = view_of(view);
    session::HeadRequest request;
    if (view.pose) request.pose = to_head_pose(*view.pose);
    if (!view.room.empty()) request.room = view.room;
    if (const std::optional<session::FieldError> problem = session::resolve_view(layout, request, v))
        return impossible::Error{session::library_message(*problem)};
    if (!lim::is_sample_count(view.samples))
        return impossible::Error{"samples " + std::to_string(view.samples) + " is not 1, 2, 4, 8 or 16"};
    return v;
}

Result<render::FrameDesc> frame_desc(const layout::Layout& layout, const View& view, const RenderOptions& options) {
    Result<math::View> resolved = resolve_view(layout, view);
    if (!resolved) return resolved;
    if (const std::optional<std::string> problem = options_problem(options)) return impossible::Error{*problem};
    render::FrameDesc frame;
    static_cast<math::View&>(frame) = *resolved;
    static_cast<render::Technique&>(frame) = technique_of(view, options);
    frame.cull_portals = options.cull;
    return frame;
}

}  // namespace impossible::api
