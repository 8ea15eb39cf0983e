// The lines `impossible walk LAYOUT --path PATH [OPTIONS]` prints, parsed:
// what the library's and the tools' walks are checked against.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace impossible::test {

inline std::vector<nlohmann::json> cli_walk(const std::string& layout, const std::string& path,
                                            const std::string& options = "") {
    const std::string command =
        std::string(IMPOSSIBLE_BINARY) + " walk '" + layout + "' --path '" + path + "' " + options;
    std::vector<nlohmann::json> lines;
    FILE* out = popen(command.c_str(), "r");
    if (out == nullptr) return lines;
    std::string text;
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, out)) > 0;) text.append(buffer, n);
    pclose(out);
    for (std::size_t at = 0, end; (end = text.find('\n', at)) != std::string::npos; at = end + 1)
        lines.push_back(nlohmann::json::parse(text.substr(at, end - at)));
    return lines;
}

}  // namespace impossible::test
