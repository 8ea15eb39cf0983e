#include "cli/args.hpp"

#include <cerrno>
#include <cstdlib>

#include "base/number_text.hpp"
#include "math/view_limits.hpp"

namespace impossible::cli {

std::optional<std::string> ParsedArgs::value(const std::string& name) const {
    const auto it = values.find(name);
    if (it == values.end()) return std::nullopt;
    return it->second;
}

ParsedArgs parse_args(const Args& args, const ArgNames& names, size_t max_positional) {
    ParsedArgs out;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "--help" || a == "-h") {
            out.help = true;
            continue;
        }
        if (a.size() > 2 && a.rfind("--", 0) == 0) {
            const size_t eq = a.find('=');
            const std::string name = a.substr(0, eq);
            if (names.with_value.count(name)) {
                if (eq != std::string::npos)
                    out.values[name] = a.substr(eq + 1);
                else if (i + 1 < args.size())
                    out.values[name] = args[++i];
                else
                    throw UsageError("option " + name + " needs a value");
            } else if (names.flags.count(name)) {
                if (eq != std::string::npos) throw UsageError("option " + name + " takes no value");
                out.flags.insert(name);
            } else {
                throw UsageError("unknown option " + name);
            }
            continue;
        }
        if (a.size() > 1 && a[0] == '-' && a != "-") throw UsageError("unknown option " + a);
        if (out.positional.size() >= max_positional) throw UsageError("unexpected argument '" + a + "'");
        out.positional.push_back(a);
    }
    return out;
}

double parse_number(const std::string& option, const std::string& text) {
    const NumberText n = read_number_text(text);
    if (!n.problem.empty()) throw InputError(option + ": '" + text + "' " + n.problem);
    return n.value;
}

int parse_int(const std::string& option, const std::string& text, int min, int max) {
    const char* begin = text.c_str();
    char* end = nullptr;
    errno = 0;
    const long v = std::strtol(begin, &end, 10);
    if (text.empty() || end != begin + text.size() || errno == ERANGE)
        throw InputError(option + ": '" + text + "' is not an integer");
    if (v < min || v > max)
        throw InputError(option + ": " + text + " is out of range " + std::to_string(min) + ".." + std::to_string(max));
    return static_cast<int>(v);
}

std::vector<double> parse_numbers(const std::string& option, const std::string& text, size_t count) {
    std::vector<double> out;
    size_t start = 0;
    while (true) {
        const size_t comma = text.find(',', start);
        out.push_back(parse_number(option, text.substr(start, comma - start)));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    if (out.size() != count)
        throw InputError(option + ": expected " + std::to_string(count) + " comma-separated numbers, got " +
                         std::to_string(out.size()));
    return out;
}

std::pair<int, int> parse_size(const std::string& option, const std::string& text) {
    const size_t x = text.find('x');
    if (x == std::string::npos) throw InputError(option + ": '" + text + "' is not WIDTHxHEIGHT");
    const int w = parse_int(option, text.substr(0, x), math::limits::kEyeSide.min, math::limits::kEyeSide.max);
    const int h = parse_int(option, text.substr(x + 1), math::limits::kEyeSide.min, math::limits::kEyeSide.max);
    return {w, h};
}

}  // namespace impossible::cli
