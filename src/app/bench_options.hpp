// The options of `impossible bench` (bench/README.md): render's view options
// plus repetitions, outputs, a scripted walk, closed portals and sweeps; and
// the configurations and poses they stand for.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/cli_args.hpp"
#include "app/view_options.hpp"
#include "layout/layout.hpp"
#include "render/frame.hpp"

namespace impossible::app {

struct BenchOptions {
    ViewOptions view;
    int frames = 20;          // timed frames per configuration and pose
    int warmup = 3;           // untimed frames first
    int profile_frames = 3;   // profiled frames (per-portal times, fragments) per configuration and pose
    std::optional<std::string> json;
    std::optional<std::string> csv;
    std::optional<std::string> path;  // a walk file: physical poses, one a line (as `walk`)
    std::optional<int> portals;       // keep only the first N portals (pairs within them)
    std::string sweep;                // "", "techniques", "portals:0,2,4,6", "depth:1,4", "size:WxH,..."
    bool error = false;               // compare every configuration with the tracer
    int reference_depth = 64;         // the tracer's recursion depth for the error
};

const std::set<std::string>& bench_value_options();
const std::set<std::string>& bench_flag_options();
const char* bench_options_help();

// Throws InputError for a bad value.
BenchOptions parse_bench_options(const ParsedArgs& args);

// The layout with only portals[0..n) kept whose targets are also among them;
// the others are closed (removed). Targets are renumbered.
layout::Layout keep_first_portals(const layout::Layout& layout, int n);

// One configuration measured: a layout variant (index into the bench's
// layouts), and the frame settings (head and room are set per pose).
struct BenchConfig {
    std::string name;   // e.g. "base", "stereo=two-pass", "portals=4"
    std::string group;  // "base", "stereo", "clip", "cull", "depth", "portals", "size"
    int layout_variant = 0;
    render::FrameDesc frame;
};

struct BenchPlan {
    std::vector<layout::Layout> layouts;  // [0]: the layout as loaded (and --portals applied)
    std::vector<BenchConfig> configs;     // [0]: the base configuration (the options as given)
};

// The configurations of the options' sweep over `layout`. Throws InputError.
BenchPlan plan_bench(const layout::Layout& layout, const BenchOptions& options);

// The virtual head and room of each frame: the options' pose (or the
// layout's start) once, or every pose of the --path walk replayed through
// the portals. Throws InputError.
struct BenchPose {
    math::HeadPose head;
    int room = 0;
};
std::vector<BenchPose> bench_poses(const layout::Layout& layout, const BenchOptions& options);

// Yaw, pitch and roll of a rotation made by math::head_rotation.
math::HeadPose head_pose_of(const math::dvec3& position, const math::dmat3& rotation);

}  // namespace impossible::app
