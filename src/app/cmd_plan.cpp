// impossible plan LAYOUT --out FILE.svg|FILE.png [--path FILE] [--png FILE.png]:
// the top-down plan of the physical floor (design/plan.hpp).
#include <iostream>

#include "app/commands.hpp"
#include "cli/layout_source.hpp"
#include "cli/option_table.hpp"
#include "cli/output_files.hpp"
#include "design/plan.hpp"
#include "image/png.hpp"
#include "layout/path_file.hpp"

namespace impossible::app {

namespace {

struct PlanOptions {
    std::string out;  // required: SVG, or PNG when it ends in .png
    std::optional<std::string> path;
    std::optional<std::string> png;
    int max_size = 1200;
};

// Described in the usage text.
constexpr Option<PlanOptions> kPlanOptions[] = {
    {"--out", "FILE.svg", nullptr, [](PlanOptions& o, const OptionValue& v) { o.out = v.text; }},
    {"--path", "FILE", nullptr, [](PlanOptions& o, const OptionValue& v) { o.path = v.text; }},
    {"--png", "FILE.png", nullptr, [](PlanOptions& o, const OptionValue& v) { o.png = v.text; }},
    {"--max-size", "PX", nullptr,
     [](PlanOptions& o, const OptionValue& v) { o.max_size = parse_int(v.name, v.text, 64, 8192); }},
};

bool ends_with(const std::string& s, const std::string& tail) {
    return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The drawing's files (SVG and/or PNG) given to `outputs`.
void set_plan_files(CommandOutputs& outputs, const PlanOptions& o, const design::Drawing& drawing) {
    const double scale = design::plan_scale(drawing, o.max_size);
    std::vector<std::string> pngs;
    if (o.png) pngs.push_back(*o.png);
    if (ends_with(o.out, ".png")) {
        pngs.push_back(o.out);
    } else {
        outputs.set(o.out, design::plan_svg(drawing, scale));
    }
    for (const std::string& png : pngs) {
        const image::Pixels image = design::plan_raster(drawing, scale);
        outputs.set(png, value_or_throw(image::encode_png(image.width, image.height, 3, image.data), png));
    }
}

}  // namespace

int run_plan_command(const Args& args, std::ostream& out, std::ostream& err) {
    const ParsedArgs parsed = parse_args(args, 1, kPlanOptions);
    if (parsed.help) {
        out << "usage: impossible plan LAYOUT --out FILE.svg [--path FILE] [--png FILE.png] [--max-size PX]\n"
               "Draws the physical floor from above: the play area, each room's floor in its own colour,\n"
               "overlaps shaded (red where likely noticed), doors with arrows to their partners, the start,\n"
               "and with --path a walk (a path file of physical head poses). An --out ending in .png writes\n"
               "a PNG instead of SVG; --png writes one as well. --max-size caps the picture (default 1200 px).\n";
        return kExitOk;
    }
    if (parsed.positional.empty()) throw UsageError("plan needs a LAYOUT file");
    if (!parsed.value("--out")) throw UsageError("plan needs --out FILE.svg");
    PlanOptions o;
    apply_options(kPlanOptions, parsed, o);
    CommandOutputs outputs;
    outputs.input("the layout", parsed.positional[0]);
    if (o.path) outputs.input("--path", *o.path);
    outputs.output("--out", o.out);
    if (o.png) outputs.output("--png", *o.png);
    const layout::Layout layout = load_layout_or_default(parsed.positional[0], outputs, err);
    std::vector<math::HeadPose> path;
    if (o.path) path = value_or_throw(layout::read_path_file(*o.path));
    const design::Report report = design::make_report(layout);
    const design::Drawing drawing = design::plan_drawing(layout, report, path);
    set_plan_files(outputs, o, drawing);
    outputs.commit();
    err << "plan: " << layout.rooms.size() << " rooms, " << (report.overlaps_exact ? "" : "at least ")
        << report.overlap_pairs << " overlapping pairs";
    if (design::overlaps_truncated(report)) err << " (" << report.overlaps.size() << " drawn)";
    err << ", " << drawing.shapes.size() << " shapes\n";
    return kExitOk;
}

}  // namespace impossible::app
