#include "cli/view_options.hpp"

#include <cmath>
#include <tuple>

#include "api/api_data.hpp"
#include "image/png.hpp"

namespace impossible::cli {

namespace {

math::HeadPose parse_pose(const OptionValue& v) {
    const std::vector<double> n = parse_numbers(v.name, v.text, 6);
    for (double x : n)
        if (std::abs(x) > 1e7) throw InputError(v.name + ": " + v.text + " has a value beyond 1e7");
    math::HeadPose pose;
    pose.position = {n[0], n[1], n[2]};
    pose.yaw_deg = n[3];
    pose.pitch_deg = n[4];
    pose.roll_deg = n[5];
    return pose;
}

gl::Backend parse_backend(const OptionValue& v) {
    if (const std::optional<gl::Backend> backend = gl::parse_backend(v.text)) return *backend;
    throw InputError(v.name + ": '" + v.text + "' is not egl or osmesa");
}

render::DepthMode parse_depth(const OptionValue& v) {
    if (v.text == "reversed-z") return render::DepthMode::ReversedZ;
    if (v.text == "standard") return render::DepthMode::Standard;
    throw InputError(v.name + ": '" + v.text + "' is not reversed-z or standard");
}

double parse_portal_texture(const OptionValue& v) {
    const double scale = parse_number(v.name, v.text);
    if (!(scale > 0.0 && scale <= 4.0)) throw InputError(v.name + ": " + v.text + " is not in (0, 4]");
    return scale;
}

// In the order of the help and of the checks (the first bad value in this
// order is the one reported).
constexpr Option<ViewOptions> kViewOptions[] = {
    {"--pose", "X,Y,Z,YAW,PITCH,ROLL", "head centre and orientation (degrees); default: the layout's start",
     [](ViewOptions& o, const OptionValue& v) { o.pose = parse_pose(v); }},
    {"--room", "ID",
     "the room the head is in; default: start.room, or with --pose the\n"
     "one room whose box holds the head",
     [](ViewOptions& o, const OptionValue& v) { o.room = v.text; }},
    {"--ipd", "M", "distance between the eyes (default 0.064)",
     [](ViewOptions& o, const OptionValue& v) { o.frame.ipd = parse_ipd(v.text); }},
    {"--fov", "DEG", "vertical field of view of each eye (default 90)",
     [](ViewOptions& o, const OptionValue& v) { o.frame.fov_y_deg = parse_fov(v.text); }},
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
     [](ViewOptions& o, const OptionValue& v) { o.frame.portal_texture_scale = parse_portal_texture(v); }},
    {"--occlusion-test", nullptr,
     "also skip portals hidden behind the room's props or walls (an\n"
     "occlusion query and conditional rendering; costs one sync a frame)",
     [](ViewOptions& o, const OptionValue&) { o.frame.occlusion_test = true; }},
    {"--samples", "N",
     "anti-aliasing: 1 (default), 2, 4, 8 or 16 samples per pixel;\n"
     "render: multisampling (the counts the driver offers; llvmpipe: 4);\n"
     "trace: supersampling at the standard sample positions",
     [](ViewOptions& o, const OptionValue& v) { o.frame.samples = parse_samples(v.text); }},
    {"--stats", nullptr, "print draw calls, triangles and portal passes to stderr",
     [](ViewOptions& o, const OptionValue&) { o.stats = true; }},
};

}  // namespace

OptionTable<ViewOptions> view_options() { return kViewOptions; }

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

ViewOptions parse_view_options(const ParsedArgs& args, OptionTable<ViewOptions> table) {
    ViewOptions o;
    if (!args.positional.empty()) o.layout_path = args.positional[0];
    apply_options(table, args, o);
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

render::FrameDesc frame_for(const layout::Layout& layout, const ViewOptions& o) {
    render::FrameDesc f = o.frame;
    if (o.pose) {
        f.head = *o.pose;
    } else {
        f.head.position = layout.start.position;
        f.head.yaw_deg = layout.start.yaw_deg;
    }
    if (o.room) {
        f.room = layout::find_room(layout, *o.room);
        if (f.room < 0) throw InputError("--room: there is no room '" + *o.room + "' in " + layout.source);
    } else if (!o.pose) {
        f.room = layout.start.room;
    } else {
        const std::vector<int> holding = api::rooms_holding(layout, f.head.position);
        if (holding.size() != 1) {
            std::string names;
            for (int i : holding) names += (names.empty() ? "" : ", ") + layout.rooms[i].id;
            throw InputError(holding.empty() ? "--pose: the head is in no room; give --room"
                                             : "--pose: the head is in several rooms (" + names + "); give --room");
        }
        f.room = holding[0];
    }
    return f;
}

}  // namespace impossible::cli
