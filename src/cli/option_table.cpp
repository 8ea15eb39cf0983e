#include "cli/option_table.hpp"

namespace impossible::cli {

std::string option_label(const char* name, const char* value_name, const char* label) {
    if (label) return label;
    std::string left = name;
    if (value_name) left += std::string(" ") + value_name;
    return left;
}

std::string help_row(std::string_view left, std::string_view help, std::size_t column) {
    constexpr std::size_t kGap = 2;
    std::string row = "  ";
    row += left;
    // A help that starts with '\n' starts on the next line (after a long LEFT).
    if (!help.starts_with('\n')) row.append(row.size() + kGap <= column ? column - row.size() : kGap, ' ');
    for (std::size_t start = 0;;) {
        const std::size_t end = help.find('\n', start);
        row += help.substr(start, end - start);
        row += '\n';
        if (end == std::string_view::npos) break;
        start = end + 1;
        row.append(column, ' ');
    }
    return row;
}

}  // namespace impossible::cli
