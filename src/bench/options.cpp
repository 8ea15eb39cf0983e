#include "bench/options.hpp"

#include <cstdio>

#include <algorithm>
#include <cmath>

#include "layout/path_file.hpp"
#include "walk/walker.hpp"

namespace impossible::bench {

using cli::apply_options;
using cli::InputError;
using cli::Option;
using cli::OptionTable;
using cli::OptionValue;
using cli::parse_int;
using cli::parse_view_options;
using cli::ParsedArgs;
using cli::view_options;
using cli::ViewOptions;
using cli::without;

namespace {

// In the order of the help and of the checks.
constexpr Option<BenchOptions> kBenchOptions[] = {
    {"--frames", "N", "timed frames per configuration and pose (default 20)",
     [](BenchOptions& o, const OptionValue& v) { o.frames = parse_int(v.name, v.text, 1, 100000); }},
    {"--warmup", "N", "untimed frames first (default 3)",
     [](BenchOptions& o, const OptionValue& v) { o.warmup = parse_int(v.name, v.text, 0, 100000); }},
    {"--profile-frames", "N",
     "profiled frames per configuration and pose (default 3): per-portal\n"
     "times and colour fragments, glFinish around each portal",
     [](BenchOptions& o, const OptionValue& v) { o.profile_frames = parse_int(v.name, v.text, 0, 100000); }},
    {"--path", "FILE",
     "a scripted walk (the `walk` path format) instead of one pose; a\n"
     "line of 18 numbers carries the hands, and line k is at time k / fps",
     [](BenchOptions& o, const OptionValue& v) { o.path = v.text; }},
    {"--fps", "N", "frames a second of --path (default 90)",
     [](BenchOptions& o, const OptionValue& v) { o.fps = cli::parse_fps(v); }},
    {"--portals", "N", "keep only the first N portals of the layout (pairs within them)",
     [](BenchOptions& o, const OptionValue& v) { o.portals = parse_int(v.name, v.text, 0, 1000000); }},
    {"--sweep", "WHAT",
     "configurations measured in one run, interleaved frame by frame:\n"
     "techniques (stereo, clip, culling, depth 1..64; implies --error),\n"
     "portals:0,2,4,6 (6/all-steps: every door pass, no cheaper steps)\n"
     "depth:1,16  size:320x180,640x360\n"
     "boxes:0,1000 (that many 12-triangle boxes on every room's floor;\n"
     "1000/all: the same without per-object culling; 1000/separate:\n"
     "one draw per run of visible props instead of a multi-draw;\n"
     "1000/all-faces: every face of a visible box, back faces too)\n"
     "samples:1,4 (multisampling; counts the driver lacks are reported)\n"
     "lights:fixed,0,1,8,32 (the fixed light, or N lights in every room)\n"
     "light-depth:0,1,2,4 (a lit layout's light depth)\n"
     "shadow-size:0,256,512 (cube shadow maps' size; 0: no prop shadows)\n"
     "mask:on,off (with --hmd: the hidden-area mask, or the same frusta\n"
     "without it)",
     [](BenchOptions& o, const OptionValue& v) { o.sweep = v.text; }},
    {"--error", nullptr, "compare each configuration with the tracer (ids, PSNR)",
     [](BenchOptions& o, const OptionValue&) { o.error = true; }},
    {"--reference-depth", "N", "the tracer's recursion depth for --error (default 64)",
     [](BenchOptions& o, const OptionValue& v) { o.reference_depth = cli::parse_max_depth(v); }},
    {"--reference-samples", "N",
     "the tracer's samples per pixel for --error (default 1; 16 for\n"
     "the anti-aliased ideal)",
     [](BenchOptions& o, const OptionValue& v) { o.reference_samples = cli::parse_samples(v); }},
    {"--json", "FILE", "write the results as JSON (schema: bench/README.md)",
     [](BenchOptions& o, const OptionValue& v) { o.json = v.text; }},
    {"--csv", "FILE", "write one CSV row per configuration",
     [](BenchOptions& o, const OptionValue& v) { o.csv = v.text; }},
};

}  // namespace

cli::ViewTables bench_view_options() {
    // Not the image files or --stats: bench writes a table and its own files.
    // Nor render's --path, --frame and --fps: bench walks all of its --path.
    static const std::vector<Option<ViewOptions>> own =
        without(view_options().own, {"--out", "--ids", "--stats", "--path", "--frame", "--fps"});
    return {own, view_options().frame};
}

OptionTable<BenchOptions> bench_options() { return kBenchOptions; }

BenchOptions parse_bench_options(const ParsedArgs& args) {
    BenchOptions o;
    o.view = parse_view_options(args, bench_view_options());
    apply_options(kBenchOptions, args, o);
    o.sweep_items = parse_sweep(o.sweep);
    o.error = o.error || o.sweep == "techniques";
    if (o.path && o.view.pose) throw InputError("--path and --pose: give one of them");
    // As render's --path (usage errors; --path and --pose kept its exit 1).
    if (o.path && args.value("--time")) throw cli::UsageError("--path and --time exclude each other");
    if (o.path && args.value("--hands")) throw cli::UsageError("--path and --hands exclude each other");
    if (o.fps && !o.path) throw cli::UsageError("--fps needs --path FILE");
    return o;
}

}  // namespace impossible::bench
