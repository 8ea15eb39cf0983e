#include "bench/options.hpp"

#include <cstdio>

#include <algorithm>
#include <cmath>

#include "layout/path_file.hpp"
#include "walk/walker.hpp"

namespace impossible::bench {

using cli::InputError;
using cli::ParsedArgs;
using cli::parse_int;
using cli::parse_view_options;
using cli::view_value_options;
namespace {

void check_sweep(const std::string& sweep) {
    if (sweep.empty() || sweep == "techniques") return;
    const size_t colon = sweep.find(':');
    const std::string kind = sweep.substr(0, colon);
    if (colon == std::string::npos || (kind != "portals" && kind != "depth" && kind != "size" && kind != "boxes" &&
                                   kind != "samples") ||
        colon + 1 == sweep.size())
        throw InputError("--sweep: '" + sweep +
                         "' is not techniques, portals:N,..., boxes:N,..., depth:N,..., size:WxH,... or samples:N,...");
}

}  // namespace

const std::set<std::string>& bench_value_options() {
    static const std::set<std::string> names = [] {
        std::set<std::string> n = view_value_options();
        n.erase("--out");
        n.erase("--ids");
        for (const char* o : {"--frames", "--warmup", "--profile-frames", "--json", "--csv", "--path", "--portals",
                              "--sweep", "--reference-depth", "--reference-samples"})
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
           "                             boxes:0,1000 (that many 12-triangle boxes on every room's floor;\n"
           "                             1000/all: the same without per-object culling; 1000/separate:\n"
           "                             one draw per run of visible props instead of a multi-draw)\n"
           "                             samples:1,4 (multisampling; counts the driver lacks are reported)\n"
           "  --error                    compare each configuration with the tracer (ids, PSNR)\n"
           "  --reference-depth N        the tracer's recursion depth for --error (default 64)\n"
           "  --reference-samples N      the tracer's samples per pixel for --error (default 1; 16 for\n"
           "                             the anti-aliased ideal)\n"
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
    if (auto v = args.value("--reference-samples")) o.reference_samples = cli::parse_samples(*v);
    check_sweep(o.sweep);
    o.error = args.flag("--error") || o.sweep == "techniques";
    if (o.path && o.view.pose) throw InputError("--path and --pose: give one of them");
    return o;
}

}  // namespace impossible::bench
