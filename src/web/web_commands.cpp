// The web build's command line (scripts/web-render): the native commands that
// need no window, run on an argument list the page passes as JSON, with
// their standard output and error kept for the page to read.
#include <emscripten.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "app/commands.hpp"
#include "cli/errors.hpp"
#include "web/web_exports.hpp"

namespace impossible::web {
namespace {

constexpr app::Command kWebCommands[] = {
    {"render", "[LAYOUT]", "one side-by-side stereo frame with the WebGL 2 rasteriser", app::run_render_command},
    {"trace", "[LAYOUT]", "the same frame with the CPU reference ray tracer", app::run_trace_command},
    {"walk", "LAYOUT --path FILE", "replay a walk and print where the head goes", app::run_walk_command},
    {"validate", "LAYOUT", "check a layout file", app::run_validate_command},
    {"compare", "A.png B.png", "compare two frames", app::run_compare_command},
};

std::string last_out, last_err;

}  // namespace

int run_web_command(const std::string& args_json) {
    last_out.clear();
    last_err.clear();
    std::ostringstream out, err;
    int status = cli::kExitUsage;
    app::Args args;
    try {
        for (const auto& a : nlohmann::json::parse(args_json)) args.push_back(a.get<std::string>());
    } catch (const std::exception& e) {
        last_err = std::string("impossible: the page passed no argument list: ") + e.what() + "\n";
        return status;
    }
    const app::Command* command = nullptr;
    for (const app::Command& c : kWebCommands)
        if (!args.empty() && args[0] == c.name) command = &c;
    if (!command) {
        err << "impossible: the web build runs render, trace, walk, validate and compare, not '"
            << (args.empty() ? std::string() : args[0]) << "'\n";
    } else {
        status = app::run_command(*command, app::Args(args.begin() + 1, args.end()), out, err);
    }
    last_out = out.str();
    last_err = err.str();
    return status;
}

const std::string& last_command_output() { return last_out; }
const std::string& last_command_errors() { return last_err; }

}  // namespace impossible::web

extern "C" {
EMSCRIPTEN_KEEPALIVE int impossible_run(const char* args_json) { return impossible::web::run_web_command(args_json); }
EMSCRIPTEN_KEEPALIVE const char* impossible_run_output() { return impossible::web::last_command_output().c_str(); }
EMSCRIPTEN_KEEPALIVE const char* impossible_run_errors() { return impossible::web::last_command_errors().c_str(); }
}
