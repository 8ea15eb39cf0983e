// impossible generate --play-area WxD | --play-area-file POLY.json --rooms N
// --seed S [--max-overlap P] [--out FILE.json]: a random valid layout
// (design/generate.hpp); standard output without --out.
#include <cstdio>
#include <iostream>

#include "app/commands.hpp"
#include "base/file_io.hpp"
#include "cli/option_table.hpp"
#include "cli/output_files.hpp"
#include "design/generate.hpp"
#include "design/play_area_file.hpp"

namespace impossible::app {

namespace {

// "W x D" in metres, centred on the origin.
math::Polygon2 parse_floor(const OptionValue& v) {
    const std::string& text = v.text;
    const std::size_t x = text.find('x');
    if (x == std::string::npos) throw InputError(v.name + ": expected WxD in metres, e.g. 4x3.5 (got '" + text + "')");
    const double w = parse_number(v.name, text.substr(0, x)), d = parse_number(v.name, text.substr(x + 1));
    if (!(w >= 1.0 && w <= 1000.0 && d >= 1.0 && d <= 1000.0))
        throw InputError(v.name + ": each side must be 1..1000 m (got '" + text + "')");
    return math::rectangle({-w / 2, -d / 2}, {w / 2, d / 2});
}

// A play-area file is a list of corners: a few kilobytes at most.
constexpr std::size_t kMaxFloorFileBytes = 4u << 20;

// The file's corners (design/play_area_file.hpp).
math::Polygon2 read_floor_file(const std::string& file) {
    const std::vector<unsigned char> bytes = value_or_throw(read_file_bytes(file, kMaxFloorFileBytes, false), file);
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    return value_or_throw(design::parse_play_area_file(text, file));
}

double parse_max_overlap(const OptionValue& v) {
    const double percent = parse_number(v.name, v.text);
    if (!(percent >= 0.0 && percent <= 100.0)) throw InputError(v.name + " must be 0..100 %");
    return percent;
}

struct GenerateArgs {
    design::GenerateOptions generate;
    std::optional<std::string> out;  // none: standard output
};

// Described in the usage text. In the order of the checks: the floor (one
// of the two; the file is read here), then the numbers.
constexpr Option<GenerateArgs> kGenerateOptions[] = {
    {"--play-area", "WxD", nullptr,
     [](GenerateArgs& o, const OptionValue& v) {
         o.generate.rectangle = true;
         o.generate.play_area = parse_floor(v);
     }},
    {"--play-area-file", "POLY.json", nullptr,
     [](GenerateArgs& o, const OptionValue& v) { o.generate.play_area = read_floor_file(v.text); }},
    {"--rooms", "N", nullptr,
     [](GenerateArgs& o, const OptionValue& v) {
         o.generate.rooms = parse_int(v.name, v.text, 1, design::kMaxGeneratedRooms);
     }},
    {"--seed", "S", nullptr,
     [](GenerateArgs& o, const OptionValue& v) {
         o.generate.seed = static_cast<std::uint64_t>(parse_int(v.name, v.text, 0, 2'000'000'000));
     }},
    {"--max-overlap", "PERCENT", nullptr,
     [](GenerateArgs& o, const OptionValue& v) { o.generate.max_overlap = parse_max_overlap(v); }},
    {"--out", "FILE.json", nullptr, [](GenerateArgs& o, const OptionValue& v) { o.out = v.text; }},
};

}  // namespace

int run_generate_command(const Args& args, std::ostream& out, std::ostream& err) {
    const ParsedArgs parsed = parse_args(args, 0, kGenerateOptions);
    if (parsed.help) {
        out << "usage: impossible generate --play-area WxD | --play-area-file POLY.json --rooms N --seed S\n"
               "                           [--max-overlap PERCENT] [--out FILE.json]\n"
               "Writes a valid layout of N rooms on the floor (a W x D m rectangle centred on the origin,\n"
               "or a polygon file: [[x, z], ...] or {\"polygon\": [...]}), each inside it and at least\n"
               "1.5 m wide, packed so that their summed floor (the expansion ratio) is as large as the\n"
               "overlap limit allows: crossing strips, turned rooms, L-shapes and curved corridors, joined\n"
               "by coincident doors into one connected space, every pair overlapping by at most PERCENT of\n"
               "the smaller floor (default: Suma et al. 2012's 56 % for rooms up to 16 m2, 31 % above).\n"
               "The same arguments write the same bytes; standard output without --out. The ratio\n"
               "reached goes to standard error.\n";
        return kExitOk;
    }
    const auto area = parsed.value("--play-area"), area_file = parsed.value("--play-area-file");
    if (!area == !area_file) throw UsageError("generate needs one of --play-area WxD or --play-area-file FILE");
    if (!parsed.value("--rooms")) throw UsageError("generate needs --rooms N");
    if (!parsed.value("--seed")) throw UsageError("generate needs --seed S");
    // The files, declared before the play-area file is read.
    CommandOutputs outputs;
    if (area_file) outputs.input("--play-area-file", *area_file);
    if (const auto file = parsed.value("--out")) outputs.output("--out", *file);
    GenerateArgs o;
    apply_options(kGenerateOptions, parsed, o);
    const design::Generated g = value_or_throw(design::generate(o.generate));
    if (o.out) {
        outputs.set(*o.out, g.text);
        outputs.commit();
        err << "generate: wrote " << g.rooms << " rooms to " << *o.out << "\n";
    } else {
        out << g.text;
    }
    char ratio[160];
    std::snprintf(ratio, sizeof ratio,
                  "generate: expansion ratio %.3f (%.2f m2 of room floor on %.2f m2 of play area)\n", g.expansion_ratio,
                  g.floor_area, g.play_area);
    err << ratio;
    return kExitOk;
}

}  // namespace impossible::app
