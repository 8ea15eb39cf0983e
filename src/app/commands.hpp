// The program's commands (cli.md); `bench` is in bench/bench_command.hpp and
// `preview` in preview/preview_command.hpp. Each takes its arguments after the command
// name and returns the exit status; errors go to `err` as one line.
#pragma once

#include <iosfwd>

#include "cli/args.hpp"

namespace impossible::app {

using cli::Args;

int run_render_command(const Args& args, std::ostream& out, std::ostream& err);
int run_validate_command(const Args& args, std::ostream& out, std::ostream& err);
int run_walk_command(const Args& args, std::ostream& out, std::ostream& err);
int run_trace_command(const Args& args, std::ostream& out, std::ostream& err);
int run_compare_command(const Args& args, std::ostream& out, std::ostream& err);
int run_plan_command(const Args& args, std::ostream& out, std::ostream& err);
int run_tour_command(const Args& args, std::ostream& out, std::ostream& err);
int run_generate_command(const Args& args, std::ostream& out, std::ostream& err);

// Dispatches argv[1] to a command; prints the overview for --help or nothing.
int run_main(const Args& args, std::ostream& out, std::ostream& err);

}  // namespace impossible::app
