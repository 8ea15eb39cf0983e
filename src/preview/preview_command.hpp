// `impossible preview [LAYOUT]` (docs/preview.md): the stereo window for
// layout designers.
#pragma once

#include <ostream>

#include "cli/args.hpp"

namespace impossible::preview {

// Takes the arguments after the command name; returns the exit status
// (errors go to `err` as one line, as for every command).
int run_preview_command(const cli::Args& args, std::ostream& out, std::ostream& err);

}  // namespace impossible::preview
