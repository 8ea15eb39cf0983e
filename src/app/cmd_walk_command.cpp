// impossible walk LAYOUT --path FILE: argument handling around run_walk.
#include <iostream>

#include "app/cmd_walk.hpp"
#include "app/commands.hpp"
#include "cli/layout_source.hpp"
#include "cli/option_table.hpp"

namespace impossible::app {

namespace {

struct WalkOptions {
    std::optional<std::string> path;  // required
};

// Described in the usage text.
constexpr Option<WalkOptions> kWalkOptions[] = {
    {"--path", "FILE", nullptr, [](WalkOptions& o, const OptionValue& v) { o.path = v.text; }},
};

}  // namespace

int run_walk_command(const Args& args, std::ostream& out, std::ostream& err) {
    const ParsedArgs parsed = parse_args(args, 1, kWalkOptions);
    if (parsed.help) {
        out << "usage: impossible walk LAYOUT --path FILE\n"
               "Replays a walk: FILE holds one physical head pose a line, X Y Z YAW PITCH ROLL\n"
               "(blank lines and lines starting with # are skipped). Prints one JSON object a line:\n"
               "{\"frame\":0,\"room\":\"hall\",\"teleports\":[],\"position\":[0,1.6,1],\"forward\":[0,0,-1]}\n"
               "FILE may be a pipe (at most 4 MiB). At most 64 portals are crossed in one frame; a frame\n"
               "that reaches the limit gets a warning on stderr.\n";
        return kExitOk;
    }
    if (parsed.positional.empty()) throw UsageError("walk needs a LAYOUT file");
    WalkOptions options;
    apply_options(kWalkOptions, parsed, options);
    if (!options.path) throw UsageError("walk needs --path FILE");
    const layout::Layout layout = load_layout_or_default(parsed.positional[0]);
    return run_walk(layout, *options.path, out, err);
}

}  // namespace impossible::app
