// What the page's script calls (web/impossible.js through cwrap): the C
// functions each file of src/web exports, declared for the files that share
// their state.
#pragma once

#include <string>

namespace impossible::web {

// Runs `impossible ARGS...` (ARGS as a JSON array of strings) with the
// commands that need no window; returns the exit status.
int run_web_command(const std::string& args_json);
const std::string& last_command_output();
const std::string& last_command_errors();

}  // namespace impossible::web
