// impossible tour LAYOUT --out PATH.txt: a walk through every reachable room
// (design/tour.hpp), written as a path file for walk, preview and bench.
#include <cmath>
#include <cstdio>
#include <iostream>

#include "app/commands.hpp"
#include "cli/layout_source.hpp"
#include "cli/option_table.hpp"
#include "cli/output_files.hpp"
#include "design/path_text.hpp"
#include "design/tour.hpp"

namespace impossible::app {

namespace {

const char* kTourUsage =
    "usage: impossible tour LAYOUT --out PATH.txt [--step M] [--head-height M]\n"
    "Plans a walk through every room a door leads to, inside the play area and around props,\n"
    "and writes it as a path file of physical head poses (the walk format) for walk,\n"
    "preview --path and bench --path. Prints the physical and virtual distance walked, the\n"
    "rooms visited (replayed with the walker) and the closest approach to the play area's edge.\n"
    "A layout with changes is walked with them (render's default eyes, 90 poses a second): the\n"
    "path file's comments and standard error say where the tour waits for a change and where\n"
    "each is made; a room it needs a change for that can never happen on its route is an error.\n";

struct TourArgs {
    std::string out;  // required
    design::TourOptions tour;
};

double parse_in_range(const OptionValue& v, double min, double max, const char* range) {
    const double x = parse_number(v.name, v.text);
    if (!(x >= min && x <= max)) throw InputError(v.name + " must be in " + range);
    return x;
}

constexpr std::size_t kTourHelpColumn = 19;
constexpr Option<TourArgs> kTourOptions[] = {
    {"--out", "PATH.txt", nullptr, [](TourArgs& o, const OptionValue& v) { o.out = v.text; }},
    {"--step", "M", "metres between poses (default 0.05)",
     [](TourArgs& o, const OptionValue& v) { o.tour.step = parse_in_range(v, 0.005, 1.0, "0.005..1 m"); }},
    {"--head-height", "M", "eye height of the walk (default 1.6)",
     [](TourArgs& o, const OptionValue& v) { o.tour.grid.head_height = parse_in_range(v, 0.2, 3.0, "0.2..3 m"); }},
};

std::string summary(const layout::Layout& layout, const design::Tour& t, std::size_t reachable) {
    char line[512];
    std::string out;
    std::snprintf(line, sizeof line, "poses: %zu\nteleports: %d\nphysical distance: %.2f m\nvirtual distance: %.2f m\n",
                  t.poses.size(), t.teleports, t.physical_distance, t.virtual_distance);
    out += line;
    out += "rooms visited: " + std::to_string(t.visited.size()) + " of " + std::to_string(reachable) + " reachable:";
    for (const int r : t.visited) out += " " + layout.rooms[r].id;
    out += "\nrooms missed:";
    if (t.missed.empty()) out += " none";
    for (const int r : t.missed) out += " " + layout.rooms[r].id;
    out += "\n";
    if (!layout.changes.empty()) {
        out += "changes made:";
        if (t.changes.empty()) out += " none";
        for (const int c : t.changes) out += " " + layout.changes[static_cast<std::size_t>(c)].id;
        out += "\n";
    }
    if (std::isfinite(t.closest_edge)) {
        std::snprintf(line, sizeof line, "closest approach to the play area's edge: %.2f m\n", t.closest_edge);
        out += line;
    } else {
        out += "closest approach to the play area's edge: n/a (no play area)\n";
    }
    return out;
}

}  // namespace

int run_tour_command(const Args& args, std::ostream& out, std::ostream& err) {
    const ParsedArgs parsed = parse_args(args, 1, kTourOptions);
    if (parsed.help) {
        out << kTourUsage << options_help(kTourOptions, kTourHelpColumn);
        return kExitOk;
    }
    if (parsed.positional.empty()) throw UsageError("tour needs a LAYOUT file");
    if (!parsed.value("--out")) throw UsageError("tour needs --out PATH.txt");
    TourArgs o;
    apply_options(kTourOptions, parsed, o);
    CommandOutputs outputs;
    outputs.input("the layout", parsed.positional[0]);
    outputs.output("--out", o.out);
    const layout::Layout layout = load_layout_or_default(parsed.positional[0], outputs, err);
    const design::Tour tour = value_or_throw(design::plan_tour(layout, o.tour));
    const std::size_t reachable = tour.visited.size() + tour.missed.size();
    const std::string report = summary(layout, tour, reachable);
    const std::string header = "impossible tour of " + layout.source + "\n" + report;
    std::vector<design::PathNote> notes;
    for (const design::TourNote& n : tour.notes) notes.emplace_back(n.pose, n.text);
    outputs.set(o.out, design::path_text(tour.poses, header, notes));
    outputs.commit();
    out << report;
    for (const design::TourNote& n : tour.notes)
        err << "note: " << (n.text.rfind("waits", 0) == 0 ? "the tour " : "") << n.text << "\n";
    for (std::size_t i = 0; i < tour.missed.size(); ++i)
        err << "warning: the tour could not reach room \"" << layout.rooms[tour.missed[i]].id << "\": " << tour.why[i]
            << "\n";
    return kExitOk;
}

}  // namespace impossible::app
