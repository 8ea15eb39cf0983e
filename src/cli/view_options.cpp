#include "cli/view_options.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <tuple>

#include "api/api_data.hpp"
#include "base/text.hpp"
#include "image/png.hpp"
#include "layout/hmd_profile.hpp"
#include "layout/path_file.hpp"
#include "lights/light_images.hpp"
#include "links/portal_links.hpp"
#include "walk/replay.hpp"

namespace impossible::cli {

namespace {

// `count` numbers of --pose or --hands, each within ±1e7.
std::vector<double> parse_pose_numbers(const std::string& name, const std::string& text, std::size_t count) {
    const std::vector<double> n = parse_numbers(name, text, count);
    for (double x : n)
        if (std::abs(x) > 1e7) throw InputError(name + ": " + text + " has a value beyond 1e7");
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

math::HeadPose parse_pose(const OptionValue& v) { return pose_at(parse_pose_numbers(v.name, v.text, 6), 0); }

gl::Backend parse_backend(const OptionValue& v) {
    if (const std::optional<gl::Backend> backend = gl::parse_backend(v.text)) return *backend;
    throw InputError(v.name + ": '" + v.text + "' is not egl or osmesa");
}

render::DepthMode parse_depth(const OptionValue& v) {
    if (v.text == "reversed-z") return render::DepthMode::ReversedZ;
    if (v.text == "standard") return render::DepthMode::Standard;
    throw InputError(v.name + ": '" + v.text + "' is not reversed-z or standard");
}

// In the order of the help and of the checks (the first bad value in this
// order is the one reported).
constexpr Option<ViewOptions> kViewOptions[] = {
    {"--pose", "X,Y,Z,YAW,PITCH,ROLL", "head centre and orientation (degrees); default: the layout's start",
     [](ViewOptions& o, const OptionValue& v) { o.pose = parse_pose(v); }},
    {"--room", "ID",
     "the room the head is in; default: start.room, or with --pose the\n"
     "one room whose box or prism holds the head",
     [](ViewOptions& o, const OptionValue& v) { o.room = v.text; }},
    {"--time", "T", "seconds: moving props stand where their motion puts them (default 0)",
     [](ViewOptions& o, const OptionValue& v) { o.frame.time = parse_number(v.name, v.text); }},
    {"--hands", "LX,LY,LZ,LYAW,LPITCH,LROLL,RX,RY,RZ,RYAW,RPITCH,RROLL",
     "\nthe left and the right hand, in the coordinates of --pose (default:\nno hands)",
     [](ViewOptions& o, const OptionValue& v) { o.frame.hands = parse_hands(v.text); }},
    {"--path", "FILE",
     "instead of --pose, --room, --time and --hands: line K of a walk\n"
     "(the `walk` path format, 6 or 18 numbers a line) after walking\n"
     "lines 0..K, with its hands, at time K / fps; needs --frame K",
     [](ViewOptions& o, const OptionValue& v) { o.path = v.text; }},
    {"--frame", "K", "the line of --path, from 0",
     [](ViewOptions& o, const OptionValue& v) { o.path_frame = parse_int(v.name, v.text, 0, 100'000'000); }},
    {"--fps", "N", "frames a second of --path: line K is at time K / N (default 90)",
     [](ViewOptions& o, const OptionValue& v) { o.fps = parse_fps(v.text); }},
    {"--ipd", "M", "distance between the eyes (default 0.064)",
     [](ViewOptions& o, const OptionValue& v) { o.frame.ipd = parse_ipd(v.text); }},
    {"--fov", "DEG", "vertical field of view of each eye (default 90)",
     [](ViewOptions& o, const OptionValue& v) { o.frame.fov_y_deg = parse_fov(v.text); }},
    {"--fov-angles", "L,R,U,D",
     "asymmetric field of view instead of --fov: the left eye's angles in\n"
     "degrees as OpenXR gives them (left, down negative), mirrored for the\n"
     "right eye; or 8 numbers, the left eye's then the right eye's",
     [](ViewOptions& o, const OptionValue& v) { o.frame.eye_optics = parse_fov_angles(v.text); }},
    {"--hmd", "FILE.json",
     "a headset profile (docs/headsets.md): each eye's angles, size and\n"
     "hidden area (masked: black, id 0), and the IPD; --size and --ipd\n"
     "replace its size and IPD",
     [](ViewOptions& o, const OptionValue& v) { o.hmd = v.text; }},
    {"--size", "WxH", "size of each eye's image (default 1280x720); the image is 2W x H",
     [](ViewOptions& o, const OptionValue& v) {
         std::tie(o.frame.eye_width, o.frame.eye_height) = parse_size(v.name, v.text);
     }},
    {"--max-depth", "N", "portals one line of sight may pass (default 8, at most 250)",
     [](ViewOptions& o, const OptionValue& v) { o.frame.max_depth = parse_int(v.name, v.text, 0, 250); }},
    {"--max-portal-passes", "N",
     "portal passes one frame may draw (trace: one pixel's ray tree;\n"
     "default 10000); past it, the remaining portals show the fill colour\n"
     "and a warning says so",
     [](ViewOptions& o, const OptionValue& v) {
         o.frame.max_portal_passes = parse_int(v.name, v.text, 0, 10'000'000);
     }},
    {"--out", "FILE.png", "side-by-side colour image (default stereo.png)",
     [](ViewOptions& o, const OptionValue& v) { o.out = v.text; }},
    {"--ids", "FILE.png", "cell-id map: 1 + room index, 0 nothing, 255 recursion limit",
     [](ViewOptions& o, const OptionValue& v) { o.ids = v.text; }},
    {"--backend", "egl|osmesa", "headless OpenGL context (default egl, falling back to osmesa)",
     [](ViewOptions& o, const OptionValue& v) { o.backend = parse_backend(v); }},
    {"--stereo", "MODE", "clip-shift (default), viewport-index or two-pass",
     [](ViewOptions& o, const OptionValue& v) { o.frame.stereo = parse_stereo(v.text); }},
    {"--clip", "MODE", "clip-distance (default) or oblique",
     [](ViewOptions& o, const OptionValue& v) { o.frame.clip = parse_clip(v.text); }},
    {"--depth", "MODE",
     "reversed-z (default: float depth, infinite far plane) or standard\n"
     "(24-bit depth, far plane at 200 km)",
     [](ViewOptions& o, const OptionValue& v) { o.frame.depth = parse_depth(v); }},
    {"--no-cull", nullptr, "draw every portal and prop without per-eye culling and scissor",
     [](ViewOptions& o, const OptionValue&) { o.frame.cull_portals = false; }},
    {"--portal-texture", "SCALE",
     "render-to-texture portals (the classic technique, for comparison):\n"
     "each portal's view at SCALE x the eye size, e.g. 0.25, 0.5, 1",
     [](ViewOptions& o, const OptionValue& v) { o.frame.portal_texture_scale = parse_portal_texture(v.name, v.text); }},
    {"--technique", "NAME",
     "stencil (default), hybrid (textures from --texture-from-level on)\n"
     "or z-clear (depth 1, doors only); docs/cli.md",
     [](ViewOptions& o, const OptionValue& v) { o.technique = parse_technique(v.name, v.text); }},
    {"--texture-from-level", "K", "hybrid: the level whose doors take textures (default 0)",
     [](ViewOptions& o, const OptionValue& v) { o.texture_from_level = parse_int(v.name, v.text, 0, 250); }},
    {"--occlusion-test", nullptr,
     "also skip portals hidden behind the room's props or walls (an\n"
     "occlusion query and conditional rendering; costs one sync a frame)",
     [](ViewOptions& o, const OptionValue&) { o.frame.occlusion_test = true; }},
    {"--samples", "N",
     "anti-aliasing: 1 (default), 2, 4, 8 or 16 samples per pixel;\n"
     "render: multisampling (the counts the driver offers; llvmpipe: 4);\n"
     "trace: supersampling at the standard sample positions",
     [](ViewOptions& o, const OptionValue& v) { o.frame.samples = parse_samples(v.text); }},
    {"--light-depth", "N",
     "portals light may pass on its way to a surface (0..16), instead of\n"
     "the layout's light_depth; only with \"lighting\": \"lights\"",
     [](ViewOptions& o, const OptionValue& v) { o.frame.light_depth = parse_light_depth(v.text); }},
    {"--shadow-size", "N",
     "texels per face side of the props' cube shadow maps (default 512,\n"
     "at most 4096; 0: props cast no shadows)",
     [](ViewOptions& o, const OptionValue& v) {
         o.frame.shadow_map_size = parse_shadow_size(v.text);
         o.shadow_options = true;
     }},
    {"--no-shadows", nullptr, "props cast no shadows (lit layouts)",
     [](ViewOptions& o, const OptionValue&) {
         o.frame.shadows = false;
         o.shadow_options = true;
     }},
    {"--stats", nullptr, "print draw calls, triangles and portal passes to stderr",
     [](ViewOptions& o, const OptionValue&) { o.stats = true; }},
};

}  // namespace

OptionTable<ViewOptions> view_options() { return kViewOptions; }

OptionTable<ViewOptions> trace_view_options() {
    static const std::vector<Option<ViewOptions>> table = without(view_options(), {"--shadow-size", "--no-shadows"});
    return table;
}

double parse_ipd(const std::string& text) {
    const double ipd = parse_number("--ipd", text);
    if (ipd < 0.0 || ipd > 10.0) throw InputError("--ipd: " + text + " is not in 0..10 m");
    return ipd;
}

double parse_fov(const std::string& text) {
    const double fov = parse_number("--fov", text);
    // Below 1 degree a pixel's angle nears single precision's resolution at
    // 8192 pixels (the rasteriser drew 1e-6 degrees as background while the
    // tracer showed a room), so narrower views are refused rather than wrong.
    if (!(fov >= kMinFovDeg && fov < 179.0))
        throw InputError("--fov: " + text + " is not in 1..179 degrees (at least 1, less than 179)");
    return fov;
}

render::StereoMode parse_stereo(const std::string& text) {
    if (text == "clip-shift") return render::StereoMode::ClipShift;
    if (text == "viewport-index") return render::StereoMode::ViewportIndex;
    if (text == "two-pass") return render::StereoMode::TwoPass;
    throw InputError("--stereo: '" + text + "' is not clip-shift, viewport-index or two-pass");
}

double parse_fps(const std::string& text) {
    const double fps = parse_number("--fps", text);
    if (!(fps >= kMinFps && fps <= kMaxFps)) throw InputError("--fps: " + text + " is not in 0.001..1000000");
    return fps;
}

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
}

void apply_hmd_profile(const std::string& path, math::View& frame, bool size_given, bool ipd_given) {
    const layout::HmdProfile profile = value_or_throw(layout::read_hmd_profile_file(path));
    frame.eye_optics = profile.eyes;
    if (!size_given) {
        frame.eye_width = profile.eye_width;
        frame.eye_height = profile.eye_height;
    }
    if (!ipd_given) frame.ipd = profile.ipd;
}

std::array<math::HeadPose, 2> parse_hands(const std::string& text) {
    const std::vector<double> n = parse_pose_numbers("--hands", text, 12);
    return {pose_at(n, 0), pose_at(n, 6)};
}

int parse_light_depth(const std::string& text) { return parse_int("--light-depth", text, 0, layout::kMaxLightDepth); }

int parse_shadow_size(const std::string& text) {
    return parse_int("--shadow-size", text, 0, render::kMaxShadowMapSize);
}

std::string light_options_warning(const layout::Layout& layout, const std::optional<int>& light_depth,
                                  bool shadow_options) {
    if (layout.lighting == layout::Lighting::Lights) {
        // The light paths' bound (docs/bounded-work.md): both renderers light
        // at most lights::kMaxLightPaths paths, at a lower depth if need be.
        const int asked = light_depth.value_or(layout.light_depth);
        const int most = lights::max_light_depth(layout, links::link_portals(layout));
        if (asked <= most) return "";
        return "warning: light depth " + std::to_string(asked) + " gives more than " +
               std::to_string(lights::kMaxLightPaths) + " light paths in " + one_line(layout.source, 1000) +
               ": lit at light depth " + std::to_string(most) + "\n";
    }
    if (!light_depth && !shadow_options) return "";
    const std::string what = light_depth && shadow_options ? "--light-depth and the shadow options have"
                             : light_depth                 ? "--light-depth has"
                                                           : "the shadow options have";
    return "warning: " + what + " no effect: " + one_line(layout.source, 1000) + "'s lighting is \"fixed\"\n";
}

int parse_samples(const std::string& text) {
    const int n = parse_int("--samples", text, 1, 16);
    if (n != 1 && n != 2 && n != 4 && n != 8 && n != 16)
        throw InputError("--samples: " + text + " is not 1, 2, 4, 8 or 16");
    return n;
}

render::ClipMode parse_clip(const std::string& text) {
    if (text == "clip-distance") return render::ClipMode::ClipDistance;
    if (text == "oblique") return render::ClipMode::Oblique;
    throw InputError("--clip: '" + text + "' is not clip-distance or oblique");
}

namespace {

bool has_option(OptionTable<ViewOptions> table, std::string_view name) {
    for (const Option<ViewOptions>& o : table)
        if (name == o.name) return true;
    return false;
}

// The usage errors of --path, --frame and --fps, before any value is read.
void check_path_combinations(const ParsedArgs& args) {
    if (args.value("--path")) {
        for (const char* other : {"--pose", "--room", "--time", "--hands"})
            if (args.value(other))
                throw UsageError(std::string("--path and ") + other +
                                 " exclude each other (line K of the path gives the head, its room, the hands and "
                                 "the time)");
        if (!args.value("--frame")) throw UsageError("--path needs --frame K, the line to draw (from 0)");
        return;
    }
    for (const char* needs_path : {"--frame", "--fps"})
        if (args.value(needs_path)) throw UsageError(std::string(needs_path) + " needs --path FILE");
}

}  // namespace

ViewOptions parse_view_options(const ParsedArgs& args, OptionTable<ViewOptions> table) {
    if (has_option(table, "--path")) check_path_combinations(args);
    check_headset_combinations(args);
    ViewOptions o;
    if (!args.positional.empty()) o.layout_path = args.positional[0];
    apply_options(table, args, o);
    if (o.hmd) apply_hmd_profile(*o.hmd, o.frame, args.value("--size").has_value(), args.value("--ipd").has_value());
    resolve_technique(o.technique, o.texture_from_level, o.frame);
    return o;
}

trace::TraceDesc trace_desc_for(const render::FrameDesc& frame, int threads) {
    trace::TraceDesc desc;
    static_cast<math::View&>(desc) = frame;
    desc.threads = threads;
    desc.samples = frame.samples;
    return desc;
}

CommandOutputs frame_outputs(const ViewOptions& options) {
    CommandOutputs outputs;
    if (options.layout_path) outputs.input("the layout", *options.layout_path);
    if (options.path) outputs.input("--path", *options.path);
    if (options.hmd) outputs.input("--hmd", *options.hmd);
    outputs.output("--out", options.out);
    if (options.ids) outputs.output("--ids", *options.ids);
    return outputs;
}

void write_frame_pngs(CommandOutputs& outputs, const ViewOptions& options, int width, int height,
                      const std::vector<std::uint8_t>& rgb, const std::vector<std::uint8_t>& ids) {
    auto encode = [&](const std::string& path, int channels, const std::vector<std::uint8_t>& pixels) {
        outputs.set(path, value_or_throw(image::encode_png(width, height, channels, pixels), path));
    };
    encode(options.out, 3, rgb);
    if (options.ids) encode(*options.ids, 1, ids);
    outputs.commit();
}

namespace {

// --path FILE --frame K [--fps N]: line K of the walk.
void set_path_frame(render::FrameDesc& f, const layout::Layout& layout, const ViewOptions& o) {
    const std::vector<layout::PathFrame> frames = value_or_throw(layout::read_path_frames_file(*o.path));
    const std::size_t k = static_cast<std::size_t>(o.path_frame.value_or(0));
    if (k >= frames.size())
        throw UsageError(
            "--frame " + std::to_string(k) + ": " + *o.path + " holds " + std::to_string(frames.size()) +
            (frames.size() == 1 ? " pose (frame 0)" : " poses (frames 0.." + std::to_string(frames.size() - 1) + ")"));
    walk::set_replayed_view(f, layout, frames, k, o.fps.value_or(layout::kDefaultPathFps));
}

// --room, else the start room without --pose, else the one room holding the head.
int room_for(const layout::Layout& layout, const ViewOptions& o, const math::dvec3& head) {
    if (o.room) {
        const int room = layout::find_room(layout, *o.room);
        if (room < 0) throw InputError("--room: there is no room '" + *o.room + "' in " + layout.source);
        return room;
    }
    if (!o.pose) return layout.start.room;
    const std::vector<int> holding = api::rooms_holding(layout, head);
    if (holding.size() != 1) {
        std::string names;
        for (int i : holding) names += (names.empty() ? "" : ", ") + layout.rooms[i].id;
        throw InputError(holding.empty() ? "--pose: the head is in no room; give --room"
                                         : "--pose: the head is in several rooms (" + names + "); give --room");
    }
    return holding[0];
}

}  // namespace

render::FrameDesc frame_for(const layout::Layout& layout, const ViewOptions& o) {
    render::FrameDesc f = o.frame;
    if (o.path) {
        set_path_frame(f, layout, o);
        return f;
    }
    if (o.pose) {
        f.head = *o.pose;
    } else {
        f.head.position = layout.start.position;
        f.head.yaw_deg = layout.start.yaw_deg;
    }
    f.room = room_for(layout, o, f.head.position);
    return f;
}

}  // namespace impossible::cli
