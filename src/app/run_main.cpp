#include <iostream>
#include <string_view>

#include "app/commands.hpp"
#include "base/text.hpp"
#include "bench/bench_command.hpp"
#include "cli/option_table.hpp"
#include "preview/preview_command.hpp"

namespace impossible::app {

namespace {

constexpr Command kCommands[] = {
    {"render", "[LAYOUT]", "one side-by-side stereo frame with the OpenGL rasteriser", run_render_command},
    {"trace", "[LAYOUT]", "the same frame with the CPU reference ray tracer", run_trace_command},
    {"compare", "A.png B.png", "compare two frames (cell ids, colour PSNR), e.g. render vs trace", run_compare_command},
    {"validate", "LAYOUT", "check a layout file; the designer's report (--json for JSON)", run_validate_command},
    {"walk", "LAYOUT --path FILE", "replay a walk and print where the head goes", run_walk_command},
    {"preview", "[LAYOUT]", "a window to walk a layout in stereo (mouse look, WASD, minimap, HUD)",
     preview::run_preview_command},
    {"bench", "[LAYOUT]", "frame time, per-portal cost, fragments and error of the renderer", bench::run_bench_command},
    {"plan", "LAYOUT --out F.svg", "a top-down drawing of the physical floor (SVG or PNG)", run_plan_command},
    {"tour", "LAYOUT --out P.txt", "a walk through every reachable room, as a path file", run_tour_command},
    {"generate", "--play-area WxD --rooms N --seed S", "a random valid layout", run_generate_command},
};

constexpr std::size_t kOverviewColumn = 27;

const Command* find_command(std::string_view name) {
    for (const Command& c : kCommands)
        if (name == c.name) return &c;
    return nullptr;
}

}  // namespace

std::span<const Command> commands() { return kCommands; }

std::string overview() {
    std::string text = "usage: impossible COMMAND [options]   (impossible COMMAND --help for more)\n";
    for (const Command& c : kCommands)
        text += cli::help_row(std::string(c.name) + " " + c.arguments, c.summary, kOverviewColumn);
    return text;
}

int run_main(const Args& args, std::ostream& out, std::ostream& err) {
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
        (args.empty() ? err : out) << overview();
        return args.empty() ? kExitUsage : kExitOk;
    }
    const std::string& name = args[0];
    const Command* command = find_command(name);
    if (!command) {
        err << "impossible: unknown command '" << one_line(name, 100) << "'\n" << overview();
        return kExitUsage;
    }
    return run_command(*command, Args(args.begin() + 1, args.end()), out, err);
}

}  // namespace impossible::app
