// impossible plan LAYOUT --out FILE.svg|FILE.png [--path FILE] [--png FILE.png]:
// the top-down plan of the physical floor (design/plan.hpp).
#include <iostream>

#include "cli/args.hpp"
#include "app/commands.hpp"
#include "cli/layout_source.hpp"
#include "image/png.hpp"
#include "cli/output_files.hpp"
#include "layout/path_file.hpp"
#include "design/plan.hpp"

namespace impossible::app {

using cli::CommandOutputs;
using cli::InputError;
using cli::kExitOk;
using cli::load_layout_or_default;
using cli::parse_args;
using cli::parse_int;
using cli::ParsedArgs;
using cli::UsageError;
using cli::value_or_throw;

namespace {

bool ends_with(const std::string& s, const std::string& tail) {
    return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

int run_plan_command(const Args& args, std::ostream& out, std::ostream& err) {
    const ParsedArgs parsed = parse_args(args, {"--out", "--path", "--png", "--max-size"}, {}, 1);
    if (parsed.help) {
        out << "usage: impossible plan LAYOUT --out FILE.svg [--path FILE] [--png FILE.png] [--max-size PX]\n"
               "Draws the physical floor from above: the play area, each room's floor in its own colour,\n"
               "overlaps shaded (red where likely noticed), doors with arrows to their partners, the start,\n"
               "and with --path a walk (a path file of physical head poses). An --out ending in .png writes\n"
               "a PNG instead of SVG; --png writes one as well. --max-size caps the picture (default 1200 px).\n";
        return kExitOk;
    }
    if (parsed.positional.empty()) throw UsageError("plan needs a LAYOUT file");
    const std::optional<std::string> out_file = parsed.value("--out");
    if (!out_file) throw UsageError("plan needs --out FILE.svg");
    const int max_size = parsed.value("--max-size") ? parse_int("--max-size", *parsed.value("--max-size"), 64, 8192) : 1200;
    CommandOutputs outputs;
    outputs.input("the layout", parsed.positional[0]);
    if (const auto file = parsed.value("--path")) outputs.input("--path", *file);
    outputs.output("--out", *out_file);
    if (const auto png = parsed.value("--png")) outputs.output("--png", *png);
    const layout::Layout layout = load_layout_or_default(parsed.positional[0]);
    std::vector<math::HeadPose> path;
    if (const auto file = parsed.value("--path")) path = value_or_throw(layout::read_path_file(*file));
    const design::Report report = design::make_report(layout);
    const design::Drawing drawing = design::plan_drawing(layout, report, path);
    const double scale = design::plan_scale(drawing, max_size);
    std::vector<std::string> pngs;
    if (const auto png = parsed.value("--png")) pngs.push_back(*png);
    if (ends_with(*out_file, ".png")) {
        pngs.push_back(*out_file);
    } else {
        outputs.set(*out_file, design::plan_svg(drawing, scale));
    }
    for (const std::string& png : pngs) {
        const image::Pixels image = design::plan_raster(drawing, scale);
        outputs.set(png, value_or_throw(image::encode_png(image.width, image.height, 3, image.data), png));
    }
    outputs.commit();
    err << "plan: " << layout.rooms.size() << " rooms, " << report.overlaps.size() << " overlapping pairs, "
        << drawing.shapes.size() << " shapes\n";
    return kExitOk;
}

}  // namespace impossible::app
