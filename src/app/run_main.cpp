#include <exception>
#include <iostream>

#include "cli/args.hpp"
#include "base/text.hpp"
#include "app/commands.hpp"
#include "bench/bench_command.hpp"
#include "preview/preview_command.hpp"

namespace impossible::app {

using cli::InputError;
using cli::kExitBadInput;
using cli::kExitOk;
using cli::kExitUsage;
using cli::UsageError;

namespace {

const char* kOverview =
    "usage: impossible COMMAND [options]   (impossible COMMAND --help for more)\n"
    "  render [LAYOUT]          one side-by-side stereo frame with the OpenGL rasteriser\n"
    "  trace [LAYOUT]           the same frame with the CPU reference ray tracer\n"
    "  compare A.png B.png      compare two frames (cell ids, colour PSNR), e.g. render vs trace\n"
    "  validate LAYOUT          check a layout file; the designer's report (--json for JSON)\n"
    "  walk LAYOUT --path FILE  replay a walk and print where the head goes\n"
    "  preview [LAYOUT]         a window to walk a layout in stereo (mouse look, WASD, minimap, HUD)\n"
    "  bench [LAYOUT]           frame time, per-portal cost, fragments and error of the renderer\n"
    "  plan LAYOUT --out F.svg  a top-down drawing of the physical floor (SVG or PNG)\n"
    "  tour LAYOUT --out P.txt  a walk through every reachable room, as a path file\n"
    "  generate --play-area WxD --rooms N --seed S   a random valid layout\n";

}  // namespace

int run_main(const Args& args, std::ostream& out, std::ostream& err) {
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
        (args.empty() ? err : out) << kOverview;
        return args.empty() ? kExitUsage : kExitOk;
    }
    const std::string& command = args[0];
    const Args rest(args.begin() + 1, args.end());
    try {
        if (command == "render") return run_render_command(rest, out, err);
        if (command == "validate") return run_validate_command(rest, out, err);
        if (command == "walk") return run_walk_command(rest, out, err);
        if (command == "trace") return run_trace_command(rest, out, err);
        if (command == "compare") return run_compare_command(rest, out, err);
        if (command == "bench") return bench::run_bench_command(rest, out, err);
        if (command == "preview") return preview::run_preview_command(rest, out, err);
        if (command == "plan") return run_plan_command(rest, out, err);
        if (command == "tour") return run_tour_command(rest, out, err);
        if (command == "generate") return run_generate_command(rest, out, err);
        err << "impossible: unknown command '" << one_line(command, 100) << "'\n" << kOverview;
        return kExitUsage;
    } catch (const UsageError& e) {
        // Messages name paths and values the user gave, which may hold
        // newlines or megabytes: each is printed as one line, cut.
        err << "impossible " << command << ": " << one_line(e.what()) << " (see impossible " << command
            << " --help)\n";
        return kExitUsage;
    } catch (const InputError& e) {
        err << "impossible " << command << ": " << one_line(e.what()) << "\n";
        return kExitBadInput;
    } catch (const std::exception& e) {
        err << "impossible " << command << ": " << one_line(e.what()) << "\n";
        return kExitBadInput;
    }
}

}  // namespace impossible::app
