// The options of `impossible bench` (bench/README.md): render's view options
// plus repetitions, outputs, a scripted walk, closed portals and sweeps; and
// the configurations and poses they stand for.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bench/sweep.hpp"
#include "cli/args.hpp"
#include "cli/option_table.hpp"
#include "cli/view_options.hpp"
#include "layout/layout.hpp"
#include "render/frame.hpp"

namespace impossible::bench {

struct BenchOptions {
    cli::ViewOptions view;
    int frames = 20;         // timed frames per configuration and pose
    int warmup = 3;          // untimed frames first
    int profile_frames = 3;  // profiled frames (per-portal times, fragments) per configuration and pose
    std::optional<std::string> json;
    std::optional<std::string> csv;
    std::optional<std::string> path;  // a walk file: physical poses, one a line (as `walk`)
    std::optional<double> fps;        // --fps of the walk: line k is at time k / fps
    std::optional<int> portals;       // keep only the first N portals (pairs within them)
    std::string sweep;                // "", "techniques", "portals:0,2,4,6", "depth:1,4", "size:WxH,...", "samples:1,4"
    std::vector<SweepItem> sweep_items;  // sweep's items, parsed (bench/sweep.hpp)
    bool error = false;                  // compare every configuration with the tracer
    int reference_depth = 64;            // the tracer's recursion depth for the error
    int reference_samples = 1;           // the tracer's samples per pixel for the error
};

// bench's options: the view options without the image files and --stats,
// then its own, both at cli::kViewHelpColumn in the help.
cli::ViewTables bench_view_options();
cli::OptionTable<BenchOptions> bench_options();

// Throws InputError for a bad value.
BenchOptions parse_bench_options(const cli::ParsedArgs& args);

}  // namespace impossible::bench
