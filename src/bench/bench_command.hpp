// `impossible bench [LAYOUT]` (bench/README.md): frame time, per-portal cost,
// fragments and counts of configurations measured in one run.
#pragma once

#include <ostream>

#include "cli/args.hpp"

namespace impossible::bench {

// Takes the arguments after the command name; returns the exit status
// (errors go to `err` as one line, as for every command).
int run_bench_command(const cli::Args& args, std::ostream& out, std::ostream& err);

}  // namespace impossible::bench
