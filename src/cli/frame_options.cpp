#include "cli/frame_options.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include <glm/geometric.hpp>

#include "layout/hmd_profile.hpp"
#include "math/eyes.hpp"
#include "math/view_limits.hpp"

namespace impossible::cli {

namespace lim = math::limits;

namespace {

// `count` numbers of --pose or --hands, each within ±kMaxPoseComponent.
std::vector<double> parse_pose_numbers(const std::string& name, const std::string& text, std::size_t count) {
    const std::vector<double> n = parse_numbers(name, text, count);
    for (double x : n)
        if (std::abs(x) > lim::kMaxPoseComponent) throw InputError(name + ": " + text + " has a value beyond 1e7");
    return n;
}

math::HeadPose pose_at(const std::vector<double>& n, std::size_t first) {
    math::HeadPose pose;
    pose.position = {n[first], n[first + 1], n[first + 2]};
    pose.yaw_deg = n[first + 3];
    pose.pitch_deg = n[first + 4];
    pose.roll_deg = n[first + 5];
    return pose;
}

// --hands: twelve numbers, the left then the right hand (as --pose).
std::array<math::HeadPose, 2> parse_hands(const OptionValue& v) {
    const std::vector<double> n = parse_pose_numbers(v.name, v.text, 12);
    return {pose_at(n, 0), pose_at(n, 6)};
}

// --eye-poses: twelve numbers, the left then the right eye's position and
// yaw, pitch and roll in the head's coordinates (as --pose): each at most
// kMaxEyeDistance from the head centre, its pitch within ±kMaxEyePitchDeg.
std::array<math::EyeOffset, 2> parse_eye_poses(const OptionValue& v) {
    const std::vector<double> n = parse_pose_numbers(v.name, v.text, 12);
    std::array<math::EyeOffset, 2> eyes;
    for (std::size_t e = 0; e < 2; ++e) {
        const math::HeadPose pose = pose_at(n, 6 * e);
        const std::string at = v.name + ": " + (e == 0 ? "left" : "right") + " eye: ";
        const double distance = glm::length(pose.position);
        if (!(distance <= lim::kMaxEyeDistance))
            throw InputError(at + "the position is " + format_number(distance) + " m from the head centre, more than " +
                             format_number(lim::kMaxEyeDistance) + " m");
        if (!(std::abs(pose.pitch_deg) <= lim::kMaxEyePitchDeg))
            throw InputError(at + "pitch " + format_number(pose.pitch_deg) + " is not within ±" +
                             format_number(lim::kMaxEyePitchDeg) + " degrees");
        eyes[e] = math::eye_offset(pose);
    }
    return eyes;
}

double parse_ipd(const OptionValue& v) {
    const double ipd = parse_number(v.name, v.text);
    if (!lim::kIpd.contains(ipd))
        throw InputError(v.name + ": " + v.text + " is not in " + lim::range_text(lim::kIpd) + " m");
    return ipd;
}

double parse_fov(const OptionValue& v) {
    const double fov = parse_number(v.name, v.text);
    // math/view_limits.hpp says why narrower views are refused.
    if (!(fov >= lim::kMinFovDeg && fov < lim::kMaxFovDeg))
        throw InputError(v.name + ": " + v.text + " is not in " + format_number(lim::kMinFovDeg) + ".." +
                         format_number(lim::kMaxFovDeg) + " degrees (at least " + format_number(lim::kMinFovDeg) +
                         ", less than " + format_number(lim::kMaxFovDeg) + ")");
    return fov;
}

render::StereoMode parse_stereo(const OptionValue& v) {
    if (v.text == "clip-shift") return render::StereoMode::ClipShift;
    if (v.text == "viewport-index") return render::StereoMode::ViewportIndex;
    if (v.text == "two-pass") return render::StereoMode::TwoPass;
    throw InputError(v.name + ": '" + v.text + "' is not clip-shift, viewport-index or two-pass");
}

render::ClipMode parse_clip(const OptionValue& v) {
    if (v.text == "clip-distance") return render::ClipMode::ClipDistance;
    if (v.text == "oblique") return render::ClipMode::Oblique;
    throw InputError(v.name + ": '" + v.text + "' is not clip-distance or oblique");
}

render::DepthMode parse_depth(const OptionValue& v) {
    if (v.text == "reversed-z") return render::DepthMode::ReversedZ;
    if (v.text == "standard") return render::DepthMode::Standard;
    throw InputError(v.name + ": '" + v.text + "' is not reversed-z or standard");
}

// In the order of the help and of the checks (the first bad value in this
// order is the one reported).
constexpr Option<FrameOptions> kViewRows[] = {
    {"--time", "T", "seconds: moving props stand where their motion puts them (default 0)",
     [](FrameOptions& o, const OptionValue& v) { o.frame.time = parse_number(v.name, v.text); }},
    {"--hands", "LX,LY,LZ,LYAW,LPITCH,LROLL,RX,RY,RZ,RYAW,RPITCH,RROLL",
     "\nthe left and the right hand, in the coordinates of --pose (default:\nno hands)",
     [](FrameOptions& o, const OptionValue& v) { o.frame.hands = parse_hands(v); }},
    {"--ipd", "M", "distance between the eyes (default 0.064)",
     [](FrameOptions& o, const OptionValue& v) { o.frame.ipd = parse_ipd(v); }},
    {"--eye-poses", "LX,LY,LZ,LYAW,LPITCH,LROLL,RX,RY,RZ,RYAW,RPITCH,RROLL",
     "\neach eye's position (m) and yaw, pitch and roll (degrees) in the\n"
     "head's coordinates, left then right, instead of --ipd (canted\n"
     "displays; default: at -+ipd/2 along x, looking the head's way)",
     [](FrameOptions& o, const OptionValue& v) { o.frame.eye_offsets = parse_eye_poses(v); }},
    {"--fov", "DEG", "vertical field of view of each eye (default 90)",
     [](FrameOptions& o, const OptionValue& v) { o.frame.fov_y_deg = parse_fov(v); }},
    {"--fov-angles", "L,R,U,D",
     "asymmetric field of view instead of --fov: the left eye's angles in\n"
     "degrees as OpenXR gives them (left, down negative), mirrored for the\n"
     "right eye; or 8 numbers, the left eye's then the right eye's",
     [](FrameOptions& o, const OptionValue& v) { o.frame.eye_optics = parse_fov_angles(v.text); }},
    {"--hmd", "FILE.json",
     "a headset profile (docs/headsets.md): each eye's angles, size and\n"
     "hidden area (masked: black, id 0), and the IPD or each eye's pose;\n"
     "--size, --ipd and --eye-poses replace its size, IPD and eye poses",
     [](FrameOptions& o, const OptionValue& v) { o.hmd = v.text; }},
    {"--size", "WxH", "size of each eye's image (default 1280x720); the image is 2W x H",
     [](FrameOptions& o, const OptionValue& v) {
         std::tie(o.frame.eye_width, o.frame.eye_height) = parse_eye_size(v);
     }},
    {"--max-depth", "N", "portals one line of sight may pass (default 8, at most 250)",
     [](FrameOptions& o, const OptionValue& v) { o.frame.max_depth = parse_max_depth(v); }},
    {"--max-portal-passes", "N",
     "portal passes one frame may draw (trace: one pixel's ray tree;\n"
     "default 10000); past it, the remaining portals show the fill colour\n"
     "and a warning says so",
     [](FrameOptions& o, const OptionValue& v) {
         o.frame.max_portal_passes = parse_int(v.name, v.text, lim::kPortalPasses.min, lim::kPortalPasses.max);
     }},
    {"--light-depth", "N",
     "portals light may pass on its way to a surface (0..16), instead of\n"
     "the layout's light_depth; only with \"lighting\": \"lights\"",
     [](FrameOptions& o, const OptionValue& v) { o.frame.light_depth = parse_light_depth(v); }},
    {"--exposure", "EV",
     "each surface's colour times 2^EV before its clamp to 0..1 (-20..20;\n"
     "default the layout's \"exposure\", else 0: the image as without it)",
     [](FrameOptions& o, const OptionValue& v) { o.frame.exposure = parse_exposure(v); }},
};

constexpr Option<FrameOptions> kTechniqueRows[] = {
    {"--stereo", "MODE", "clip-shift (default), viewport-index or two-pass",
     [](FrameOptions& o, const OptionValue& v) { o.frame.stereo = parse_stereo(v); }},
    {"--clip", "MODE", "clip-distance (default) or oblique",
     [](FrameOptions& o, const OptionValue& v) { o.frame.clip = parse_clip(v); }},
    {"--depth", "MODE",
     "reversed-z (default: float depth, infinite far plane) or standard\n"
     "(24-bit depth, far plane at 200 km)",
     [](FrameOptions& o, const OptionValue& v) { o.frame.depth = parse_depth(v); }},
    {"--portal-texture", "SCALE",
     "render-to-texture portals (the classic technique, for comparison):\n"
     "each portal's view at SCALE x the eye size, e.g. 0.25, 0.5, 1",
     [](FrameOptions& o, const OptionValue& v) {
         o.frame.portal_texture_scale = parse_portal_texture(v.name, v.text);
     }},
    {"--technique", "NAME",
     "stencil (default), hybrid (textures from --texture-from-level on)\n"
     "or z-clear (depth 1, doors only); docs/cli.md",
     [](FrameOptions& o, const OptionValue& v) { o.technique = parse_technique(v.name, v.text); }},
    {"--texture-from-level", "K", "hybrid: the level whose doors take textures (default 0)",
     [](FrameOptions& o, const OptionValue& v) { o.texture_from_level = parse_max_depth(v); }},
    {"--occlusion-test", nullptr,
     "also skip portals hidden behind the room's props or walls (an\n"
     "occlusion query and conditional rendering; costs one sync a frame)",
     [](FrameOptions& o, const OptionValue&) { o.frame.occlusion_test = true; }},
    {"--samples", "N",
     "anti-aliasing: 1 (default), 2, 4, 8 or 16 samples per pixel;\n"
     "render: multisampling (the counts the driver offers; llvmpipe: 4);\n"
     "trace: supersampling at the standard sample positions",
     [](FrameOptions& o, const OptionValue& v) { o.frame.samples = parse_samples(v); }},
    {"--shadow-size", "N",
     "texels per face side of the props' cube shadow maps (default 512,\n"
     "at most 4096; 0: props cast no shadows)",
     [](FrameOptions& o, const OptionValue& v) {
         o.frame.shadow_map_size = parse_shadow_size(v);
         o.shadow_options = true;
     }},
    {"--no-shadows", nullptr, "props cast no shadows (lit layouts)",
     [](FrameOptions& o, const OptionValue&) {
         o.frame.shadows = false;
         o.shadow_options = true;
     }},
};

constexpr Option<FrameOptions> kDiagnosticRows[] = {
    {"--no-cull", nullptr, "draw every portal and prop without per-eye culling and scissor",
     [](FrameOptions& o, const OptionValue&) { o.frame.cull_portals = false; }},
};

// --hmd FILE: the profile's optics into `frame`, and its eye size and IPD
// or eye poses unless --size, --ipd or --eye-poses replace them; throws
// InputError FILE:LINE:COLUMN: field: message for a bad profile, and for
// --ipd with a profile that gives each eye's pose.
void apply_hmd_profile(const std::string& path, math::View& frame, const ParsedArgs& args) {
    const layout::HmdProfile profile = value_or_throw(layout::read_hmd_profile_file(path));
    frame.eye_optics = profile.eyes;
    if (!args.value("--size")) {
        frame.eye_width = profile.eye_width;
        frame.eye_height = profile.eye_height;
    }
    if (args.value("--eye-poses")) return;  // the eyes as given, not the profile's
    if (profile.eye_poses && args.value("--ipd"))
        throw InputError("--ipd: " + path +
                         " gives each eye's position and orientation, which --ipd cannot replace; give "
                         "--eye-poses instead");
    if (profile.eye_poses)
        frame.eye_offsets = {math::eye_offset((*profile.eye_poses)[0]), math::eye_offset((*profile.eye_poses)[1])};
    else if (!args.value("--ipd"))
        frame.ipd = profile.ipd;
}

}  // namespace

OptionTable<FrameOptions> view_rows() { return kViewRows; }
OptionTable<FrameOptions> technique_rows() { return kTechniqueRows; }
OptionTable<FrameOptions> diagnostic_rows() { return kDiagnosticRows; }

math::HeadPose parse_pose(const OptionValue& v) { return pose_at(parse_pose_numbers(v.name, v.text, 6), 0); }

double parse_fps(const OptionValue& v) {
    const double fps = parse_number(v.name, v.text);
    if (!lim::kFps.contains(fps)) throw InputError(v.name + ": " + v.text + " is not in " + lim::range_text(lim::kFps));
    return fps;
}

int parse_max_depth(const OptionValue& v) { return parse_int(v.name, v.text, lim::kMaxDepth.min, lim::kMaxDepth.max); }

int parse_samples(const OptionValue& v) {
    const int n =
        parse_int(v.name, v.text, lim::kSampleCounts[0], lim::kSampleCounts[std::size(lim::kSampleCounts) - 1]);
    if (!lim::is_sample_count(n)) throw InputError(v.name + ": " + v.text + " is not 1, 2, 4, 8 or 16");
    return n;
}

int parse_light_depth(const OptionValue& v) {
    return parse_int(v.name, v.text, lim::kLightDepth.min, lim::kLightDepth.max);
}

double parse_exposure(const OptionValue& v) {
    const double ev = parse_number(v.name, v.text);
    if (!lim::kExposure.contains(ev))
        throw InputError(v.name + ": " + v.text + " is out of range " + lim::range_text(lim::kExposure));
    return ev;
}

int parse_shadow_size(const OptionValue& v) {
    return parse_int(v.name, v.text, lim::kShadowMapSize.min, lim::kShadowMapSize.max);
}

std::pair<int, int> parse_eye_size(const OptionValue& v) { return parse_size(v.name, v.text); }

std::array<math::EyeOptics, 2> parse_fov_angles(const std::string& text) {
    const std::size_t commas = static_cast<std::size_t>(std::count(text.begin(), text.end(), ','));
    const std::vector<double> n = parse_numbers("--fov-angles", text, commas >= 7 ? 8 : 4);
    std::array<math::EyeOptics, 2> eyes;
    eyes[0].fov = {n[0], n[1], n[2], n[3]};
    eyes[1].fov = n.size() == 8 ? math::FovAngles{n[4], n[5], n[6], n[7]} : math::mirrored(eyes[0].fov);
    for (int e = 0; e < 2; ++e)
        if (const std::optional<std::string> problem = layout::fov_angles_problem(eyes[static_cast<size_t>(e)].fov))
            throw InputError("--fov-angles: " + std::string(e == 0 ? "left" : "right") + " eye: " + *problem);
    return eyes;
}

void check_headset_combinations(const ParsedArgs& args) {
    const bool fov = args.value("--fov").has_value(), angles = args.value("--fov-angles").has_value(),
               hmd = args.value("--hmd").has_value();
    if (fov && angles) throw UsageError("--fov and --fov-angles exclude each other");
    if (fov && hmd) throw UsageError("--fov and --hmd exclude each other (the profile gives each eye's angles)");
    if (angles && hmd)
        throw UsageError("--fov-angles and --hmd exclude each other (the profile gives each eye's angles)");
    if (args.value("--eye-poses") && args.value("--ipd"))
        throw UsageError(
            "--eye-poses and --ipd exclude each other (the eyes' positions give the distance between them)");
}

void finish_frame_options(const ParsedArgs& args, FrameOptions& o) {
    if (o.hmd) apply_hmd_profile(*o.hmd, o.frame, args);
    resolve_technique(o.technique, o.texture_from_level, o.frame);
}

}  // namespace impossible::cli
