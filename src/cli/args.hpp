// Command-line parsing shared by every command (cli.md): "--name VALUE" takes
// the next argument as the value even when it starts with '-', and
// "--name=VALUE" works too. Flags take no value. Commands name their options
// in tables (cli/option_table.hpp), from which the names here are drawn.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "cli/errors.hpp"

namespace impossible::cli {

// A command's arguments, after the command name.
using Args = std::vector<std::string>;

struct ParsedArgs {
    std::vector<std::string> positional;
    std::map<std::string, std::string> values;  // "--pose" → "1,2,3,0,0,0"
    std::set<std::string> flags;                // "--stats"
    bool help = false;

    std::optional<std::string> value(const std::string& name) const;
    bool flag(const std::string& name) const { return flags.count(name) != 0; }
};

// The options a command accepts (e.g. "--pose"): those that take a value, and flags.
struct ArgNames {
    std::set<std::string> with_value;
    std::set<std::string> flags;
};

// Throws UsageError for an option not in `names`, a missing value, a value
// given to a flag, or more than max_positional positional arguments.
ParsedArgs parse_args(const Args& args, const ArgNames& names, size_t max_positional);

// Value parsers; they throw InputError naming the option.
double parse_number(const std::string& option, const std::string& text);
int parse_int(const std::string& option, const std::string& text, int min, int max);
std::vector<double> parse_numbers(const std::string& option, const std::string& text, size_t count);
std::pair<int, int> parse_size(const std::string& option, const std::string& text);

}  // namespace impossible::cli
