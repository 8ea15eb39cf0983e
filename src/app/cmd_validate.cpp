// impossible validate LAYOUT: every problem, or a short summary.
#include <iostream>

#include "app/cli_args.hpp"
#include "app/commands.hpp"
#include "layout/layout.hpp"

namespace impossible::app {

int run_validate_command(const Args& args, std::ostream& out, std::ostream& err) {
    const ParsedArgs parsed = parse_args(args, {}, {}, 1);
    if (parsed.help) {
        out << "usage: impossible validate LAYOUT\n"
               "Checks a layout file; prints a summary (rooms, portals, pairs, rooms outside the play\n"
               "area, expansion ratio) or every problem as FILE:LINE:COLUMN: message (exit 1).\n";
        return kExitOk;
    }
    if (parsed.positional.empty()) throw UsageError("validate needs a LAYOUT file");
    const layout::LoadResult loaded = layout::load_layout_file(parsed.positional[0]);
    if (!loaded.errors.empty()) {
        for (const layout::Diagnostic& d : loaded.errors) err << d.str() << "\n";
        return kExitBadInput;
    }
    for (const layout::Diagnostic& d : loaded.warnings) err << "warning: " << d.str() << "\n";
    const layout::Layout& l = *loaded.layout;
    out << layout::summary_text(l, layout::summarize(l));
    return kExitOk;
}

}  // namespace impossible::app
