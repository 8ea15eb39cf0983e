// impossible walk LAYOUT --path FILE: argument handling around run_walk.
#include <iostream>

#include "app/cmd_walk.hpp"
#include "app/commands.hpp"
#include "cli/errors.hpp"
#include "cli/frame_options.hpp"
#include "cli/layout_source.hpp"
#include "cli/option_table.hpp"
#include "layout/path_file.hpp"
#include "session/session.hpp"

namespace impossible::app {

namespace {

struct WalkOptions {
    std::optional<std::string> path;  // required
    double fps = layout::kDefaultPathFps;
    bool stats = false;
};

// Described in the usage text.
constexpr Option<WalkOptions> kWalkOptions[] = {
    {"--path", "FILE", nullptr, [](WalkOptions& o, const OptionValue& v) { o.path = v.text; }},
    {"--fps", "N", nullptr, [](WalkOptions& o, const OptionValue& v) { o.fps = parse_fps(v); }},
    {"--stats", nullptr, nullptr, [](WalkOptions& o, const OptionValue&) { o.stats = true; }},
};

// render's view options that place the eyes of the seen test (cli.md, walk).
OptionTable<FrameOptions> walk_view_rows() {
    static const std::vector<Option<FrameOptions>> rows =
        without(view_rows(), {"--time", "--hands", "--max-portal-passes", "--light-depth", "--exposure"});
    return rows;
}

}  // namespace

int run_walk_command(const Args& args, std::ostream& out, std::ostream& err) {
    const ParsedArgs parsed = parse_args(args, 1, kWalkOptions, walk_view_rows());
    if (parsed.help) {
        out << "usage: impossible walk LAYOUT --path FILE [--fps N] [--stats] [view options]\n"
               "Replays a walk: FILE holds one physical head pose a line, X Y Z YAW PITCH ROLL, or 18\n"
               "numbers: the head, then the left and the right hand (blank lines and lines starting\n"
               "with # are skipped). Prints one JSON object a line:\n"
               "{\"frame\":0,\"room\":\"hall\",\"teleports\":[],\"position\":[0,1.6,1],\"forward\":[0,0,-1]}\n"
               "with \"hands\":[\"ROOM\",\"ROOM\"] on a line with hands, and, when props move,\n"
               "\"props\":{\"ID\":\"ROOM\",...}: each moving prop's room at time k / N for line k\n"
               "(--fps N: frames per second, 0.001..1000000, default 90).\n"
               "FILE may be a pipe (at most 4 MiB). At most 64 portals are crossed in one frame; a frame\n"
               "that reaches the limit gets a warning on stderr.\n"
               "A layout with \"changes\" is walked with the pairing in force: a line has\n"
               "\"changes\":[\"ID\",...] at the frame a change is made, where neither eye sees a door it\n"
               "affects; the eyes are placed by render's view options (docs/changes.md). --stats prints\n"
               "the seen test's cost to stderr: frames it ran, portal passes, median and largest time.\n\n"
            << options_help(walk_view_rows(), kViewHelpColumn);
        return kExitOk;
    }
    if (parsed.positional.empty()) throw UsageError("walk needs a LAYOUT file");
    WalkOptions options;
    apply_options(kWalkOptions, parsed, options);
    check_headset_combinations(parsed);
    FrameOptions view;
    apply_options(walk_view_rows(), parsed, view);
    finish_frame_options(parsed, view);
    if (!options.path) throw UsageError("walk needs --path FILE");
    const session::Session session(load_layout_or_default(parsed.positional[0]));
    return run_walk(session, *options.path, out, err, {options.fps, view.frame, options.stats});
}

}  // namespace impossible::app
