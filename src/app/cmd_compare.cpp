// impossible compare A.png B.png [--ids-a A_IDS.png --ids-b B_IDS.png]
//                   [--diff OUT.png] [--max-mismatch PERCENT] [--min-psnr DB]
// Compares two frames of one view, typically `render` against `trace`
// (metrics in src/trace/image_compare.hpp).
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "cli/option_table.hpp"
#include "cli/output_files.hpp"
#include "image/compare.hpp"
#include "image/png.hpp"

namespace impossible::app {

namespace {

const char* kCompareUsage =
    "usage: impossible compare A.png B.png [--ids-a A_IDS.png --ids-b B_IDS.png] [--diff OUT.png]\n"
    "                          [--max-mismatch PERCENT] [--min-psnr DB]\n"
    "Compares two frames of the same view, e.g. a render against a trace:\n"
    "  impossible compare render.png trace.png --ids-a render-ids.png --ids-b trace-ids.png\n"
    "Prints one line of key=value pairs to standard output:\n"
    "  pixels, psnr_db (colour PSNR over every pixel and channel, inf when equal), max_error\n"
    "  (largest channel difference, 0..255) and, with id maps, id_mismatches and id_mismatch_pct\n"
    "  (a pixel is a mismatch unless each map's id there occurs in the other map within one\n"
    "  pixel, its 3x3 neighbourhood, so edges one pixel apart count nothing), interior_pixels,\n"
    "  interior_psnr_db and interior_max_error (colour over pixels at least one pixel away from\n"
    "  any id edge in both maps), flat_pixels, flat_psnr_db and flat_max_error (the interior less\n"
    "  the pixels on a checker's or texture's edge, where a neighbour differs by more than 8\n"
    "  levels: there a sub-pixel shift flips a pixel to the other tile, so interior_max_error\n"
    "  is large on a correct render against its trace, e.g. 139, and flat_max_error small).\n";

const char* kCompareNotes =
    "The PNGs are checked (CRCs, truncation, at most 2 x 8192 x 8192 pixels); id maps must be 8-bit\n"
    "grey. --diff must not name an input.\n"
    "Exit status: 0 alike within the limits, 1 past a limit or for unreadable or different-sized\n"
    "images, 2 for a usage error.\n";

struct CompareOptions {
    std::optional<std::string> ids_a, ids_b;  // both or neither
    std::optional<std::string> diff;
    std::optional<double> max_mismatch;  // percent
    std::optional<double> min_psnr;      // dB
};

double parse_percentage(const OptionValue& v) {
    const double percent = parse_number(v.name, v.text);
    if (percent < 0.0 || percent > 100.0) throw InputError(v.name + ": " + v.text + " is not a percentage in 0..100");
    return percent;
}

constexpr std::size_t kCompareHelpColumn = 30;
constexpr Option<CompareOptions> kCompareOptions[] = {
    {"--ids-a", "FILE", "the cell-id maps of A and B (give both or neither)",
     [](CompareOptions& o, const OptionValue& v) { o.ids_a = v.text; }, "--ids-a FILE, --ids-b FILE"},
    {"--ids-b", "FILE", nullptr, [](CompareOptions& o, const OptionValue& v) { o.ids_b = v.text; }},
    {"--diff", "OUT.png",
     "a picture of the differences: A in dim grey, colour errors x8 in\n"
     "green, id mismatches in red",
     [](CompareOptions& o, const OptionValue& v) { o.diff = v.text; }},
    {"--max-mismatch", "PERCENT", "exit 1 when id_mismatch_pct exceeds it (needs the id maps)",
     [](CompareOptions& o, const OptionValue& v) { o.max_mismatch = parse_percentage(v); }},
    {"--min-psnr", "DB", "exit 1 when psnr_db is below it",
     [](CompareOptions& o, const OptionValue& v) { o.min_psnr = parse_number(v.name, v.text); }},
};

// The usage errors of option combinations, before any value is read.
void check_combinations(const ParsedArgs& parsed) {
    if (parsed.positional.size() != 2) throw UsageError("compare needs two images, A.png and B.png");
    const bool ids = parsed.value("--ids-a").has_value();
    if (ids != parsed.value("--ids-b").has_value()) throw UsageError("give both --ids-a and --ids-b, or neither");
    if (parsed.value("--max-mismatch") && !ids)
        throw UsageError("--max-mismatch needs the id maps (--ids-a and --ids-b)");
}

// Reads a colour PNG (grey is widened to rgb).
std::vector<std::uint8_t> read_colour(const std::string& path, int& width, int& height) {
    image::Pixels png = value_or_throw(image::read_png(path));
    width = png.width;
    height = png.height;
    if (png.channels == 3) return std::move(png.data);
    std::vector<std::uint8_t> rgb;
    rgb.reserve(3 * png.data.size());
    for (std::uint8_t v : png.data) rgb.insert(rgb.end(), {v, v, v});
    return rgb;
}

std::vector<std::uint8_t> read_ids(const std::string& path, int width, int height) {
    image::Pixels png = value_or_throw(image::read_png(path));
    // A 16-bit map would decode to its high bytes (all 0 for small ids).
    if (png.channels != 1 || png.bit_depth != 8)
        throw InputError(path + ": a cell-id map must be an 8-bit greyscale PNG (this one is " +
                         std::to_string(png.bit_depth) + "-bit" + (png.channels == 1 ? "" : " colour") + ")");
    if (png.width != width || png.height != height)
        throw InputError(path + ": the id map is " + std::to_string(png.width) + "x" + std::to_string(png.height) +
                         ", its colour image " + std::to_string(width) + "x" + std::to_string(height));
    return std::move(png.data);
}

// The two frames, with their id maps when given.
std::pair<image::Image, image::Image> read_frames(const ParsedArgs& parsed, const CompareOptions& o) {
    image::Image a, b;
    a.rgb = read_colour(parsed.positional[0], a.width, a.height);
    b.rgb = read_colour(parsed.positional[1], b.width, b.height);
    if (a.width != b.width || a.height != b.height)
        throw InputError(parsed.positional[0] + " is " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                         " but " + parsed.positional[1] + " is " + std::to_string(b.width) + "x" +
                         std::to_string(b.height));
    if (o.ids_a) {
        a.ids = read_ids(*o.ids_a, a.width, a.height);
        b.ids = read_ids(*o.ids_b, b.width, b.height);
    }
    if (auto why = image::incomparable(a, b)) throw InputError(*why);
    return {std::move(a), std::move(b)};
}

}  // namespace

int run_compare_command(const Args& args, std::ostream& out, std::ostream& err) {
    const ParsedArgs parsed = parse_args(args, 2, kCompareOptions);
    if (parsed.help) {
        out << kCompareUsage << options_help(kCompareOptions, kCompareHelpColumn) << kCompareNotes;
        return kExitOk;
    }
    check_combinations(parsed);
    CompareOptions o;
    apply_options(kCompareOptions, parsed, o);
    CommandOutputs outputs;
    outputs.input("image A", parsed.positional[0]);
    outputs.input("image B", parsed.positional[1]);
    if (o.ids_a) outputs.input("--ids-a", *o.ids_a);
    if (o.ids_b) outputs.input("--ids-b", *o.ids_b);
    if (o.diff) outputs.output("--diff", *o.diff);

    const auto [a, b] = read_frames(parsed, o);
    const image::Comparison c = image::compare_pictures(a, b);
    if (o.diff) {
        const std::vector<std::uint8_t> picture = image::diff_picture(a, b);
        outputs.set(*o.diff, value_or_throw(image::encode_png(a.width, a.height, 3, picture), *o.diff));
        outputs.commit();
    }
    out << image::summary_line(c) << "\n";
    if (o.max_mismatch && c.id_mismatch_percent > *o.max_mismatch) {
        err << "impossible compare: " << c.id_mismatch_percent
            << "% of the pixels have mismatched ids, more than --max-mismatch " << *o.max_mismatch << "%\n";
        return kExitBadInput;
    }
    if (o.min_psnr && c.psnr_db < *o.min_psnr) {
        err << "impossible compare: colour PSNR " << c.psnr_db << " dB is below --min-psnr " << *o.min_psnr << " dB\n";
        return kExitBadInput;
    }
    return kExitOk;
}

}  // namespace impossible::app
