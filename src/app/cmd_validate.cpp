// impossible validate LAYOUT [--json]: every problem, or a short summary and
// the designer's report (design/report.hpp).
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "base/text.hpp"
#include "cli/option_table.hpp"
#include "design/report.hpp"
#include "layout/layout.hpp"

namespace impossible::app {

namespace {

const char* kValidateUsage =
    "usage: impossible validate LAYOUT [--json]\n"
    "Checks a layout file; prints a summary (rooms, portals, pairs, rooms outside the play\n"
    "area, expansion ratio; door pairs, window pairs and mirrors where there are mirrors or\n"
    "windows) and the designer's report (room overlaps against Suma et al. 2012,\n"
    "rooms no door leads to, rooms and doors outside the play area as walked; with changes,\n"
    "each change's condition, pairs and the rooms it makes reachable), or every\n"
    "problem as FILE:LINE:COLUMN: message (exit 1). Findings are warnings (exit 0).\n";

struct ValidateOptions {
    bool json = false;
};

constexpr std::size_t kValidateHelpColumn = 10;
constexpr Option<ValidateOptions> kValidateOptions[] = {
    {"--json", nullptr, "the whole report (or the errors) as one JSON document on standard output",
     [](ValidateOptions& o, const OptionValue&) { o.json = true; }},
};

}  // namespace

int run_validate_command(const Args& args, std::ostream& out, std::ostream& err) {
    const ParsedArgs parsed = parse_args(args, 1, kValidateOptions);
    if (parsed.help) {
        out << kValidateUsage << options_help(kValidateOptions, kValidateHelpColumn);
        return kExitOk;
    }
    if (parsed.positional.empty()) throw UsageError("validate needs a LAYOUT file");
    ValidateOptions options;
    apply_options(kValidateOptions, parsed, options);
    const bool json = options.json;
    const layout::LoadResult loaded = layout::load_layout_file(parsed.positional[0]);
    if (!loaded.errors.empty()) {
        for (const layout::Diagnostic& d : loaded.errors) err << d.str() << "\n";
        if (json) out << design::errors_json(parsed.positional[0], loaded.errors).dump(2) << "\n";
        return kExitBadInput;
    }
    for (const layout::Diagnostic& d : loaded.warnings) err << "warning: " << d.str() << "\n";
    const layout::Layout& l = *loaded.layout;
    const design::Report report = design::make_report(l);
    for (const std::string& f : report.findings) err << "warning: " << one_line(l.source, 1000) << ": " << f << "\n";
    if (json) {
        out << design::report_json(l, report, loaded.warnings).dump(2) << "\n";
    } else {
        out << layout::summary_text(l, report.summary) << design::report_text(l, report);
    }
    return kExitOk;
}

}  // namespace impossible::app
