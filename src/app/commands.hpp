// The program's commands (cli.md), in one table that run_main dispatches
// from and prints the overview from; `bench` is in bench/bench_command.hpp
// and `preview` in preview/preview_command.hpp. Each takes its arguments
// after the command name and returns the exit status; errors go to `err` as
// one line.
#pragma once

#include <iosfwd>
#include <span>
#include <string>

#include "cli/args.hpp"

namespace impossible::app {

// Every command speaks the command line's vocabulary (src/cli: arguments,
// option tables, errors, outputs, view options), so app uses it unqualified.
using namespace cli;

int run_render_command(const Args& args, std::ostream& out, std::ostream& err);
int run_validate_command(const Args& args, std::ostream& out, std::ostream& err);
int run_walk_command(const Args& args, std::ostream& out, std::ostream& err);
int run_trace_command(const Args& args, std::ostream& out, std::ostream& err);
int run_compare_command(const Args& args, std::ostream& out, std::ostream& err);
int run_plan_command(const Args& args, std::ostream& out, std::ostream& err);
int run_tour_command(const Args& args, std::ostream& out, std::ostream& err);
int run_generate_command(const Args& args, std::ostream& out, std::ostream& err);

// One command: its name, its arguments and one line for the overview, and
// what runs it (UsageError and InputError become the exit status).
struct Command {
    const char* name;       // "render"
    const char* arguments;  // "[LAYOUT]", shown after the name in the overview
    const char* summary;
    int (*run)(const Args& args, std::ostream& out, std::ostream& err);
};

// Every command, in the overview's order.
std::span<const Command> commands();

// `impossible --help`: the usage line and a line for each command.
std::string overview();

// Runs one command on its arguments (those after its name): UsageError and
// InputError become the exit status and one line on `err` (run_command.cpp;
// the web build's dispatcher shares it).
int run_command(const Command& command, const Args& rest, std::ostream& out, std::ostream& err);

// Dispatches args[0] to a command; prints the overview for --help or nothing.
int run_main(const Args& args, std::ostream& out, std::ostream& err);

}  // namespace impossible::app
