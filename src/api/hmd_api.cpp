// Headset profiles through the public API: impossible::api::load_hmd_profile
// reads one as `--hmd` does, use_hmd_profile sets a View from it; eye_pose
// turns --eye-poses' angles into an eye's pose.
#include "api/api_data.hpp"
#include "layout/hmd_profile.hpp"

namespace impossible::api {

namespace {

EyeOptics public_optics(const math::EyeOptics& eye) {
    EyeOptics out;
    out.fov = {eye.fov.left, eye.fov.right, eye.fov.up, eye.fov.down};
    out.visible_area.reserve(eye.visible_area.size());
    for (const glm::dvec2& c : eye.visible_area) out.visible_area.push_back({c.x, c.y});
    return out;
}

}  // namespace

Expected<HmdProfile> load_hmd_profile(const std::string& path) {
    return no_throw([&]() -> Expected<HmdProfile> {
        Result<layout::HmdProfile> read = layout::read_hmd_profile_file(path);
        if (!read) return Error{read.error()};
        HmdProfile out;
        out.name = read->name;
        out.source = read->source;
        out.ipd = read->ipd;
        out.eye_width = read->eye_width;
        out.eye_height = read->eye_height;
        out.eyes = {public_optics(read->eyes[0]), public_optics(read->eyes[1])};
        if (read->eye_poses)
            out.eye_poses =
                std::array<EyePose, 2>{to_eye_pose((*read->eye_poses)[0]), to_eye_pose((*read->eye_poses)[1])};
        return out;
    });
}

void use_hmd_profile(View& view, const HmdProfile& profile) {
    view.eye_optics = profile.eyes;
    view.width = profile.eye_width;
    view.height = profile.eye_height;
    view.ipd = profile.ipd;
    view.eye_poses = profile.eye_poses;
}

EyePose eye_pose(const Pose& pose) {
    return to_eye_pose({{pose.x, pose.y, pose.z}, math::angles_quaternion(to_head_pose(pose))});
}

}  // namespace impossible::api
