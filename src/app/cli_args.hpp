// Command-line parsing shared by every command (cli.md): "--name VALUE" takes
// the next argument as the value even when it starts with '-', and
// "--name=VALUE" works too. Flags take no value.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace impossible::app {

// Exit statuses of cli.md.
inline constexpr int kExitOk = 0;
inline constexpr int kExitBadInput = 1;
inline constexpr int kExitUsage = 2;

// A usage error (unknown option, missing value): exit status 2.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};
// Wrong input (bad value, bad layout, unknown room): exit status 1.
struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct ParsedArgs {
    std::vector<std::string> positional;
    std::map<std::string, std::string> values;  // "--pose" → "1,2,3,0,0,0"
    std::set<std::string> flags;                // "--stats"
    bool help = false;

    std::optional<std::string> value(const std::string& name) const;
    bool flag(const std::string& name) const { return flags.count(name) != 0; }
};

// `with_value` and `flags` list the options a command accepts (e.g. "--pose").
// Throws UsageError for anything else.
ParsedArgs parse_args(const std::vector<std::string>& args, const std::set<std::string>& with_value,
                      const std::set<std::string>& flags, size_t max_positional);

// Value parsers; they throw InputError naming the option.
double parse_number(const std::string& option, const std::string& text);
int parse_int(const std::string& option, const std::string& text, int min, int max);
std::vector<double> parse_numbers(const std::string& option, const std::string& text, size_t count);
std::pair<int, int> parse_size(const std::string& option, const std::string& text);

}  // namespace impossible::app
