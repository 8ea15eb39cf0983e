// impossible compare A.png B.png [--ids-a A_IDS.png --ids-b B_IDS.png]
//                   [--diff OUT.png] [--max-mismatch PERCENT] [--min-psnr DB]
// Compares two frames of one view, typically `render` against `trace`
// (metrics in src/trace/image_compare.hpp).
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "cli/args.hpp"
#include "app/commands.hpp"
#include "cli/output_files.hpp"
#include "image/png.hpp"
#include "image/compare.hpp"

namespace impossible::app {

using cli::CommandOutputs;
using cli::InputError;
using cli::kExitBadInput;
using cli::kExitOk;
using cli::parse_args;
using cli::parse_number;
using cli::ParsedArgs;
using cli::UsageError;
using cli::value_or_throw;

namespace {

const char* kCompareHelp =
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
    "  any id edge in both maps).\n"
    "  --ids-a FILE, --ids-b FILE  the cell-id maps of A and B (give both or neither)\n"
    "  --diff OUT.png              a picture of the differences: A in dim grey, colour errors x8 in\n"
    "                              green, id mismatches in red\n"
    "  --max-mismatch PERCENT      exit 1 when id_mismatch_pct exceeds it (needs the id maps)\n"
    "  --min-psnr DB               exit 1 when psnr_db is below it\n"
    "The PNGs are checked (CRCs, truncation, at most 2 x 8192 x 8192 pixels); id maps must be 8-bit\n"
    "grey. --diff must not name an input.\n"
    "Exit status: 0 alike within the limits, 1 past a limit or for unreadable or different-sized\n"
    "images, 2 for a usage error.\n";

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

}  // namespace

int run_compare_command(const Args& args, std::ostream& out, std::ostream& err) {
    const ParsedArgs parsed =
        parse_args(args, {"--ids-a", "--ids-b", "--diff", "--max-mismatch", "--min-psnr"}, {}, 2);
    if (parsed.help) {
        out << kCompareHelp;
        return kExitOk;
    }
    if (parsed.positional.size() != 2) throw UsageError("compare needs two images, A.png and B.png");
    const auto ids_a = parsed.value("--ids-a"), ids_b = parsed.value("--ids-b");
    if (ids_a.has_value() != ids_b.has_value()) throw UsageError("give both --ids-a and --ids-b, or neither");
    std::optional<double> max_mismatch, min_psnr;
    if (auto v = parsed.value("--max-mismatch")) {
        if (!ids_a) throw UsageError("--max-mismatch needs the id maps (--ids-a and --ids-b)");
        max_mismatch = parse_number("--max-mismatch", *v);
        if (*max_mismatch < 0.0 || *max_mismatch > 100.0)
            throw InputError("--max-mismatch: " + *v + " is not a percentage in 0..100");
    }
    if (auto v = parsed.value("--min-psnr")) min_psnr = parse_number("--min-psnr", *v);
    CommandOutputs outputs;
    outputs.input("image A", parsed.positional[0]);
    outputs.input("image B", parsed.positional[1]);
    if (ids_a) outputs.input("--ids-a", *ids_a);
    if (ids_b) outputs.input("--ids-b", *ids_b);
    const std::optional<std::string> diff = parsed.value("--diff");
    if (diff) outputs.output("--diff", *diff);

    image::Image a, b;
    a.rgb = read_colour(parsed.positional[0], a.width, a.height);
    b.rgb = read_colour(parsed.positional[1], b.width, b.height);
    if (a.width != b.width || a.height != b.height)
        throw InputError(parsed.positional[0] + " is " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                         " but " + parsed.positional[1] + " is " + std::to_string(b.width) + "x" +
                         std::to_string(b.height));
    if (ids_a) {
        a.ids = read_ids(*ids_a, a.width, a.height);
        b.ids = read_ids(*ids_b, b.width, b.height);
    }
    if (auto why = image::incomparable(a, b)) throw InputError(*why);

    const image::Comparison c = image::compare_pictures(a, b);
    if (diff) {
        outputs.set(*diff, value_or_throw(image::encode_png(a.width, a.height, 3, image::diff_picture(a, b)), *diff));
        outputs.commit();
    }
    out << image::summary_line(c) << "\n";
    if (max_mismatch && c.id_mismatch_percent > *max_mismatch) {
        err << "impossible compare: " << c.id_mismatch_percent
            << "% of the pixels have mismatched ids, more than --max-mismatch " << *max_mismatch << "%\n";
        return kExitBadInput;
    }
    if (min_psnr && c.psnr_db < *min_psnr) {
        err << "impossible compare: colour PSNR " << c.psnr_db << " dB is below --min-psnr " << *min_psnr << " dB\n";
        return kExitBadInput;
    }
    return kExitOk;
}

}  // namespace impossible::app
