// A command's options as one table of plain data: each option's name, the
// name of its value (none for a flag), its help text and its parser, declared
// once. parse_args learns from the tables which names take a value and which
// are flags, apply_options runs the parsers, and options_help writes the
// help's option list, so the three can never disagree.
//
//   constexpr Option<TourOptions> kTourOptions[] = {
//       {"--step", "M", "metres between poses (default 0.05)",
//        [](TourOptions& o, const OptionValue& v) { o.step = parse_number(v.name, v.text); }},
//   };
//   const ParsedArgs parsed = parse_args(args, 1, kTourOptions);
//   if (parsed.help) out << options_help(kTourOptions, 19);
//   TourOptions options;
//   apply_options(kTourOptions, parsed, options);
//
// A command may take several tables (render's view options, and trace's own
// after them), each filling in its own struct.
#pragma once

#include <cassert>
#include <cstddef>
#include <initializer_list>
#include <iterator>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "cli/args.hpp"

namespace impossible::cli {

// What a parser is given: the option's name, for messages, and its value
// ("" for a flag).
struct OptionValue {
    std::string name;  // "--fov"
    std::string text;  // "200"
};

// One option of a command, filling in the options struct T.
template <class T>
struct Option {
    const char* name;        // "--pose"
    const char* value_name;  // "X,Y,Z,YAW,PITCH,ROLL"; nullptr: a flag, which takes no value
    // The help; '\n' starts a line of its own, indented like the first.
    // nullptr: not listed (the command's text, or another option's label, describes it).
    const char* help;
    // Runs when the option is given (a value given twice: the last one);
    // throws InputError for a bad value.
    void (*parse)(T& options, const OptionValue& value);
    const char* label = nullptr;    // the help's left column instead of "NAME VALUE_NAME"
    const char* heading = nullptr;  // a line of its own before the option's help
};

// A command's table, or a part of it.
template <class T>
using OptionTable = std::span<const Option<T>>;

// The help's left column of an option: "--size WxH", "--no-cull", or its label.
std::string option_label(const char* name, const char* value_name, const char* label);

// One line of a help table: "  LEFT", then the help from `column` (0-based),
// at least two spaces after a longer LEFT; each further line of the help
// ('\n') indented to the column (a help that starts with '\n' starts on the
// line after LEFT). Ends with '\n'.
std::string help_row(std::string_view left, std::string_view help, std::size_t column);

// The option list of a help text, in table order.
template <class Table>
std::string options_help(const Table& table, std::size_t column) {
    std::string out;
    for (const auto& o : table) {
        if (o.heading) out += std::string(o.heading) + "\n";
        if (o.help) out += help_row(option_label(o.name, o.value_name, o.label), o.help, column);
    }
    return out;
}

// Adds the table's names to `names`; each name is declared once, across the
// tables of a command too.
template <class Table>
void add_option_names(ArgNames& names, const Table& table) {
    for (const auto& o : table) {
        [[maybe_unused]] const bool added = (o.value_name ? names.with_value : names.flags).insert(o.name).second;
        assert(added && !(names.with_value.count(o.name) && names.flags.count(o.name)));
    }
}

// Reads the arguments against the options of the tables; throws UsageError for
// an option no table has, a missing value, a value given to a flag, or more
// than max_positional positional arguments.
template <class... Tables>
ParsedArgs parse_args(const Args& args, std::size_t max_positional, const Tables&... tables) {
    ArgNames names;
    (add_option_names(names, tables), ...);
    return parse_args(args, names, max_positional);
}

// Runs the parser of every option of the table that was given, in table
// order (so the first bad value in that order is the one reported).
template <class Table, class T>
void apply_options(const Table& table, const ParsedArgs& parsed, T& options) {
    for (const auto& o : table) {
        if (!o.value_name) {
            if (parsed.flag(o.name)) o.parse(options, {o.name, ""});
        } else if (const std::optional<std::string> value = parsed.value(o.name)) {
            o.parse(options, {o.name, *value});
        }
    }
}

// The table without the named options (bench: the view options without the
// image files).
template <class Table>
auto without(const Table& table, std::initializer_list<std::string_view> names) {
    std::vector<std::iter_value_t<decltype(std::begin(table))>> kept;
    for (const auto& o : table) {
        bool dropped = false;
        for (std::string_view n : names) dropped = dropped || n == o.name;
        if (!dropped) kept.push_back(o);
    }
    return kept;
}

}  // namespace impossible::cli
