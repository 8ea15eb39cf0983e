#include "cli/view_options.hpp"

#include "image/png.hpp"

#include <cmath>
#include <tuple>

namespace impossible::cli {

const std::set<std::string>& view_value_options() {
    static const std::set<std::string> names = {"--pose", "--room",  "--ipd", "--fov",     "--size",
                                                "--max-depth", "--out", "--ids", "--backend", "--stereo",
                                                "--clip", "--depth", "--portal-texture", "--samples",
                                                "--max-portal-passes"};
    return names;
}

const std::set<std::string>& view_flag_options() {
    static const std::set<std::string> names = {"--no-cull", "--occlusion-test", "--stats"};
    return names;
}

const char* view_options_help() {
    return "  --pose X,Y,Z,YAW,PITCH,ROLL  head centre and orientation (degrees); default: the layout's start\n"
           "  --room ID                  the room the head is in; default: start.room, or with --pose the\n"
           "                             one room whose box holds the head\n"
           "  --ipd M                    distance between the eyes (default 0.064)\n"
           "  --fov DEG                  vertical field of view of each eye (default 90)\n"
           "  --size WxH                 size of each eye's image (default 1280x720); the image is 2W x H\n"
           "  --max-depth N              portals one line of sight may pass (default 8, at most 250)\n"
           "  --max-portal-passes N      portal passes one frame may draw (default 10000); past it, the\n"
           "                             remaining portals show the fill colour and a warning says so\n"
           "  --out FILE.png             side-by-side colour image (default stereo.png)\n"
           "  --ids FILE.png             cell-id map: 1 + room index, 0 nothing, 255 recursion limit\n"
           "  --backend egl|osmesa       headless OpenGL context (default egl, falling back to osmesa)\n"
           "  --stereo MODE              clip-shift (default), viewport-index or two-pass\n"
           "  --clip MODE                clip-distance (default) or oblique\n"
           "  --depth MODE               reversed-z (default: float depth, infinite far plane) or standard\n"
           "                             (24-bit depth, far plane at 200 km)\n"
           "  --no-cull                  draw every portal and prop without per-eye culling and scissor\n"
           "  --portal-texture SCALE     render-to-texture portals (the classic technique, for comparison):\n"
           "                             each portal's view at SCALE x the eye size, e.g. 0.25, 0.5, 1\n"
           "  --occlusion-test           also skip portals hidden behind the room's props or walls (an\n"
           "                             occlusion query and conditional rendering; costs one sync a frame)\n"
           "  --samples N                anti-aliasing: 1 (default), 2, 4, 8 or 16 samples per pixel;\n"
           "                             render: multisampling (the counts the driver offers; llvmpipe: 4);\n"
           "                             trace: supersampling at the standard sample positions\n"
           "  --stats                    print draw calls, triangles and portal passes to stderr\n";
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

ViewOptions parse_view_options(const ParsedArgs& args) {
    ViewOptions o;
    if (!args.positional.empty()) o.layout_path = args.positional[0];
    if (auto v = args.value("--pose")) {
        const std::vector<double> n = parse_numbers("--pose", *v, 6);
        math::HeadPose pose;
        pose.position = {n[0], n[1], n[2]};
        pose.yaw_deg = n[3];
        pose.pitch_deg = n[4];
        pose.roll_deg = n[5];
        for (double x : n)
            if (std::abs(x) > 1e7) throw InputError("--pose: " + *v + " has a value beyond 1e7");
        o.pose = pose;
    }
    if (auto v = args.value("--room")) o.room = *v;
    if (auto v = args.value("--ipd")) o.frame.ipd = parse_ipd(*v);
    if (auto v = args.value("--fov")) o.frame.fov_y_deg = parse_fov(*v);
    if (auto v = args.value("--size")) std::tie(o.frame.eye_width, o.frame.eye_height) = parse_size("--size", *v);
    if (auto v = args.value("--max-depth")) o.frame.max_depth = parse_int("--max-depth", *v, 0, 250);
    if (auto v = args.value("--max-portal-passes"))
        o.frame.max_portal_passes = parse_int("--max-portal-passes", *v, 0, 10'000'000);
    if (auto v = args.value("--out")) o.out = *v;
    if (auto v = args.value("--ids")) o.ids = *v;
    if (auto v = args.value("--backend")) {
        o.backend = gl::parse_backend(*v);
        if (!o.backend) throw InputError("--backend: '" + *v + "' is not egl or osmesa");
    }
    if (auto v = args.value("--stereo")) o.frame.stereo = parse_stereo(*v);
    if (auto v = args.value("--clip")) o.frame.clip = parse_clip(*v);
    if (auto v = args.value("--depth")) {
        if (*v == "reversed-z") o.frame.depth = render::DepthMode::ReversedZ;
        else if (*v == "standard") o.frame.depth = render::DepthMode::Standard;
        else throw InputError("--depth: '" + *v + "' is not reversed-z or standard");
    }
    o.frame.cull_portals = !args.flag("--no-cull");
    o.frame.occlusion_test = args.flag("--occlusion-test");
    if (auto v = args.value("--portal-texture")) {
        o.frame.portal_texture_scale = parse_number("--portal-texture", *v);
        if (!(o.frame.portal_texture_scale > 0.0 && o.frame.portal_texture_scale <= 4.0))
            throw InputError("--portal-texture: " + *v + " is not in (0, 4]");
    }
    if (auto v = args.value("--samples")) o.frame.samples = parse_samples(*v);
    o.stats = args.flag("--stats");
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
        std::vector<int> holding;
        const math::dvec3 p = f.head.position;
        for (size_t i = 0; i < layout.rooms.size(); ++i) {
            const layout::Room& r = layout.rooms[i];
            if (p.x >= r.min.x && p.x <= r.max.x && p.y >= r.min.y && p.y <= r.max.y && p.z >= r.min.z &&
                p.z <= r.max.z)
                holding.push_back(static_cast<int>(i));
        }
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
