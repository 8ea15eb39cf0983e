// impossible bench [LAYOUT] [options]: frame time, per-portal cost, colour
// fragments, draw calls and portal passes, and optionally the error against
// the tracer, of one or several configurations (bench/README.md).
#include <iostream>

#include "bench/bench_command.hpp"
#include "bench/options.hpp"
#include "bench/report.hpp"
#include "bench/run.hpp"
#include "cli/layout_source.hpp"
#include "cli/option_table.hpp"
#include "cli/output_files.hpp"
#include "gl/context.hpp"

namespace impossible::bench {

using cli::kExitOk;
using cli::kViewHelpColumn;
using cli::load_layout_or_default;
using cli::options_help;
using cli::parse_args;
using cli::ParsedArgs;
using cli::value_or_throw;

namespace {

const char* kHelp =
    "usage: impossible bench [LAYOUT] [options]\n"
    "Measures the OpenGL renderer at fixed poses (or along a scripted walk): wall-clock frame time\n"
    "(glFinish and a monotonic clock; medians and 10th-90th percentiles), CPU submission time, the\n"
    "time of each visible portal's subtree, colour fragments per output pixel (GL_SAMPLES_PASSED\n"
    "over the colour passes), draw calls, triangles and portal passes. Configurations of a sweep are\n"
    "measured in one run, interleaved frame by frame. Prints a table; see bench/README.md.\n\n";

}  // namespace

int run_bench_command(const cli::Args& args, std::ostream& out, std::ostream& err) {
    const cli::ViewTables tables = bench_view_options();
    const ParsedArgs parsed = parse_args(args, 1, tables.own, tables.frame, bench_options());
    if (parsed.help) {
        out << kHelp << cli::view_help(tables) << options_help(bench_options(), kViewHelpColumn);
        return kExitOk;
    }
    const BenchOptions options = parse_bench_options(parsed);
    cli::CommandOutputs outputs;
    if (options.view.layout_path) outputs.input("the layout", *options.view.layout_path);
    if (options.path) outputs.input("--path", *options.path);
    if (options.view.hmd) outputs.input("--hmd", *options.view.hmd);
    if (options.json) outputs.output("--json", *options.json);
    if (options.csv) outputs.output("--csv", *options.csv);
    const session::Session session(load_layout_or_default(options.view.layout_path, outputs));
    err << cli::model_warnings_text(session)
        << cli::light_options_warning(session, options.view.frame.light_depth, options.view.shadow_options);
    std::vector<session::Session> stages;  // the pairings a walk through changes puts in force
    const std::vector<BenchPose> poses = bench_poses(session, options, &stages);
    BenchPlan plan = plan_bench(session, options);
    add_stages(plan, stages, options);

    std::string fallback_note;
    const gl::Context context =
        value_or_throw(gl::create_context_with_fallback(options.view.backend, &fallback_note), "no OpenGL 4.5 context");
    if (!fallback_note.empty()) err << "note: " << fallback_note << "\n";

    const BenchResult result = run_bench(plan, poses, options, context.state(), context.renderer);
    write_bench_table(result, options, out);
    if (options.json) outputs.set(*options.json, bench_json(result, options));
    if (options.csv) outputs.set(*options.csv, bench_csv(result));
    outputs.commit();
    return kExitOk;
}

}  // namespace impossible::bench
