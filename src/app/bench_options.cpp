#include "app/bench_options.hpp"

#include <cstdio>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "app/preview_path.hpp"
#include "scene/walk.hpp"

namespace impossible::app {
namespace {

std::vector<std::string> split(const std::string& text, char sep) {
    std::vector<std::string> parts;
    std::stringstream in(text);
    std::string part;
    while (std::getline(in, part, sep)) parts.push_back(part);
    return parts;
}

void check_sweep(const std::string& sweep) {
    if (sweep.empty() || sweep == "techniques") return;
    const size_t colon = sweep.find(':');
    const std::string kind = sweep.substr(0, colon);
    if (colon == std::string::npos || (kind != "portals" && kind != "depth" && kind != "size" && kind != "boxes") ||
        colon + 1 == sweep.size())
        throw InputError("--sweep: '" + sweep +
                         "' is not techniques, portals:N,..., boxes:N,..., depth:N,... or size:WxH,...");
}

}  // namespace

const std::set<std::string>& bench_value_options() {
    static const std::set<std::string> names = [] {
        std::set<std::string> n = view_value_options();
        n.erase("--out");
        n.erase("--ids");
        for (const char* o : {"--frames", "--warmup", "--profile-frames", "--json", "--csv", "--path", "--portals",
                              "--sweep", "--reference-depth"})
            n.insert(o);
        return n;
    }();
    return names;
}

const std::set<std::string>& bench_flag_options() {
    static const std::set<std::string> names = {"--no-cull", "--occlusion-test", "--error"};
    return names;
}

const char* bench_options_help() {
    return "  --frames N                 timed frames per configuration and pose (default 20)\n"
           "  --warmup N                 untimed frames first (default 3)\n"
           "  --profile-frames N         profiled frames per configuration and pose (default 3): per-portal\n"
           "                             times and colour fragments, glFinish around each portal\n"
           "  --path FILE                a scripted walk (the `walk` path format) instead of one pose\n"
           "  --portals N                keep only the first N portals of the layout (pairs within them)\n"
           "  --sweep WHAT               configurations measured in one run, interleaved frame by frame:\n"
           "                             techniques (stereo, clip, culling, depth 1..64; implies --error),\n"
           "                             portals:0,2,4,6  depth:1,16  size:320x180,640x360\n"
           "                             boxes:0,1000 (that many 12-triangle boxes on every room's floor)\n"
           "  --error                    compare each configuration with the tracer (ids, PSNR)\n"
           "  --reference-depth N        the tracer's recursion depth for --error (default 64)\n"
           "  --json FILE                write the results as JSON (schema: bench/README.md)\n"
           "  --csv FILE                 write one CSV row per configuration\n";
}

BenchOptions parse_bench_options(const ParsedArgs& args) {
    BenchOptions o;
    o.view = parse_view_options(args);
    if (auto v = args.value("--frames")) o.frames = parse_int("--frames", *v, 1, 100000);
    if (auto v = args.value("--warmup")) o.warmup = parse_int("--warmup", *v, 0, 100000);
    if (auto v = args.value("--profile-frames")) o.profile_frames = parse_int("--profile-frames", *v, 0, 100000);
    if (auto v = args.value("--json")) o.json = *v;
    if (auto v = args.value("--csv")) o.csv = *v;
    if (auto v = args.value("--path")) o.path = *v;
    if (auto v = args.value("--portals")) o.portals = parse_int("--portals", *v, 0, 1000000);
    if (auto v = args.value("--sweep")) o.sweep = *v;
    if (auto v = args.value("--reference-depth")) o.reference_depth = parse_int("--reference-depth", *v, 0, 250);
    check_sweep(o.sweep);
    o.error = args.flag("--error") || o.sweep == "techniques";
    if (o.path && o.view.pose) throw InputError("--path and --pose: give one of them");
    return o;
}

layout::Layout keep_first_portals(const layout::Layout& layout, int n) {
    layout::Layout out = layout;
    out.portals.clear();
    std::vector<int> renumbered(layout.portals.size(), -1);
    for (size_t i = 0; i < layout.portals.size(); ++i) {
        const int target = layout.portals[i].target;
        if (static_cast<int>(i) < n && target < n) {
            renumbered[i] = static_cast<int>(out.portals.size());
            out.portals.push_back(layout.portals[i]);
        }
    }
    for (layout::Portal& p : out.portals) p.target = renumbered[p.target];
    return out;
}

// The layout with `n` small boxes (12 triangles each) added on the floor of
// every room, in a grid: scene triangles without changing which rooms show.
layout::Layout with_extra_boxes(const layout::Layout& layout, int n) {
    layout::Layout out = layout;
    const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
    for (layout::Room& room : out.rooms) {
        const glm::dvec3 extent = room.max - room.min;
        const double size = 0.4 * std::min(extent.x, extent.z) / std::max(side, 1);
        for (int i = 0; i < n; ++i) {
            layout::BoxProp box;
            const double x = room.min.x + (i % side + 0.5) * extent.x / side;
            const double z = room.min.z + (i / side + 0.5) * extent.z / side;
            box.min = {x - 0.5 * size, room.min.y, z - 0.5 * size};
            box.max = {x + 0.5 * size, room.min.y + size, z + 0.5 * size};
            box.color = {0.7, 0.5, 0.3};
            room.props.push_back(box);
        }
    }
    return out;
}

BenchPlan plan_bench(const layout::Layout& layout, const BenchOptions& o) {
    BenchPlan plan;
    plan.layouts.push_back(o.portals ? keep_first_portals(layout, *o.portals) : layout);
    // Head and room come per pose; frame_for only needs a valid room here.
    ViewOptions view = o.view;
    view.pose.reset();
    view.room.reset();
    render::FrameDesc base = frame_for(plan.layouts[0], view);
    plan.configs.push_back({"base", "base", 0, base});
    auto add = [&](const std::string& name, const std::string& group, auto change) {
        BenchConfig c{name, group, 0, base};
        change(c);
        plan.configs.push_back(c);
    };
    if (o.sweep == "techniques") {
        add("stereo=two-pass", "stereo", [](BenchConfig& c) { c.frame.stereo = render::StereoMode::TwoPass; });
        add("stereo=viewport-index", "stereo",
            [](BenchConfig& c) { c.frame.stereo = render::StereoMode::ViewportIndex; });
        add("clip=oblique", "clip", [](BenchConfig& c) { c.frame.clip = render::ClipMode::Oblique; });
        add("clip=clip-distance", "clip", [](BenchConfig& c) { c.frame.clip = render::ClipMode::ClipDistance; });
        add("cull=off", "cull", [](BenchConfig& c) { c.frame.cull_portals = false; });
        add("cull=on", "cull", [](BenchConfig& c) { c.frame.cull_portals = true; });
        add("occlusion=on", "occlusion", [](BenchConfig& c) { c.frame.occlusion_test = true; });
        for (double scale : {0.25, 0.5, 1.0}) {
            char name[32];
            std::snprintf(name, sizeof name, "texture=%g", scale);
            add(name, "technique", [scale](BenchConfig& c) { c.frame.portal_texture_scale = scale; });
        }
        for (int d : {1, 2, 4, 8, 16, 64})
            add("depth=" + std::to_string(d), "depth", [d](BenchConfig& c) { c.frame.max_depth = d; });
        return plan;
    }
    if (o.sweep.empty()) return plan;
    const size_t colon = o.sweep.find(':');
    const std::string kind = o.sweep.substr(0, colon);
    for (const std::string& item : split(o.sweep.substr(colon + 1), ',')) {
        const std::string name = kind + "=" + item;
        if (kind == "portals") {
            const int n = parse_int("--sweep portals", item, 0, 1000000);
            plan.layouts.push_back(keep_first_portals(layout, n));
            add(name, kind, [&](BenchConfig& c) { c.layout_variant = static_cast<int>(plan.layouts.size()) - 1; });
        } else if (kind == "boxes") {
            const int n = parse_int("--sweep boxes", item, 0, 100000);
            plan.layouts.push_back(with_extra_boxes(plan.layouts[0], n));
            add(name, kind, [&](BenchConfig& c) { c.layout_variant = static_cast<int>(plan.layouts.size()) - 1; });
        } else if (kind == "depth") {
            const int d = parse_int("--sweep depth", item, 0, 250);
            add(name, kind, [d](BenchConfig& c) { c.frame.max_depth = d; });
        } else {
            const auto [w, h] = parse_size("--sweep size", item);
            add(name, kind, [w = w, h = h](BenchConfig& c) {
                c.frame.eye_width = w;
                c.frame.eye_height = h;
            });
        }
    }
    return plan;
}

math::HeadPose head_pose_of(const math::dvec3& position, const math::dmat3& r) {
    // R = R_y(yaw) · R_x(pitch) · R_z(-roll): its third column is
    // (sin yaw cos pitch, -sin pitch, cos yaw cos pitch) and its second row
    // (-cos pitch sin roll, cos pitch cos roll, -sin pitch). glm is column-major.
    constexpr double deg = 180.0 / 3.14159265358979323846;
    math::HeadPose pose;
    pose.position = position;
    pose.pitch_deg = std::asin(std::clamp(-r[2][1], -1.0, 1.0)) * deg;
    pose.yaw_deg = std::atan2(r[2][0], r[2][2]) * deg;
    pose.roll_deg = std::atan2(-r[0][1], r[1][1]) * deg;
    return pose;
}

std::vector<BenchPose> bench_poses(const layout::Layout& layout, const BenchOptions& o) {
    if (!o.path) {
        const render::FrameDesc f = frame_for(layout, o.view);
        return {{f.head, f.room}};
    }
    const PathFile file = read_path_file(*o.path);
    if (!file.error.empty()) throw InputError(file.error);
    if (file.poses.empty()) throw InputError(*o.path + ": the path holds no pose");
    scene::Walker walker(layout);
    std::vector<BenchPose> poses;
    for (const math::HeadPose& physical : file.poses) {
        walker.step(physical);
        poses.push_back({head_pose_of(walker.position(), walker.rotation()), walker.room()});
    }
    return poses;
}

}  // namespace impossible::app
