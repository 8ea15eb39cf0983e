#include "bench/sweep.hpp"

#include <sstream>
#include <string_view>
#include <tuple>

#include "cli/frame_options.hpp"
#include "layout/limits.hpp"

namespace impossible::bench {

namespace {

using cli::InputError;

std::vector<std::string> split(const std::string& text, char sep) {
    std::vector<std::string> parts;
    std::stringstream in(text);
    std::string part;
    while (std::getline(in, part, sep)) parts.push_back(part);
    return parts;
}

constexpr std::string_view kKinds[] = {"portals", "depth",       "size",        "boxes", "samples",
                                       "lights",  "light-depth", "shadow-size", "mask",  "volumes"};

// "N" or "N/SUFFIX" for one of `suffixes`: N, and the suffix found.
std::string split_suffix(const std::string& item, std::initializer_list<const char*> suffixes, SweepItem& out) {
    for (const char* s : suffixes) {
        const std::string suffix = std::string("/") + s;
        if (item.size() > suffix.size() && item.ends_with(suffix)) {
            out.suffix = s;
            return item.substr(0, item.size() - suffix.size());
        }
    }
    return item;
}

SweepItem parse_item(const std::string& kind, const std::string& item) {
    SweepItem s;
    s.kind = kind;
    s.name = kind + "=" + item;
    const cli::OptionValue value{"--sweep " + kind, item};
    if (kind == "portals") {
        s.n = cli::parse_int(value.name, split_suffix(item, {"all-steps"}, s), 0, 1'000'000);
    } else if (kind == "boxes") {
        s.n = cli::parse_int(value.name, split_suffix(item, {"all-faces", "all", "separate"}, s), 0, 100'000);
    } else if (kind == "samples") {
        s.n = cli::parse_samples(value);
    } else if (kind == "lights") {
        const std::string n = split_suffix(item, {"naive", "one-part", "no-cache"}, s);
        s.n = n == "fixed" ? -1 : cli::parse_int(value.name, n, 0, static_cast<int>(layout::limits::kMaxLightsPerRoom));
        if (s.n < 0 && !s.suffix.empty())
            throw InputError(value.name + ": 'fixed/" + s.suffix + "' has no lights to test");
    } else if (kind == "light-depth") {
        s.n = cli::parse_light_depth(value);
    } else if (kind == "shadow-size") {
        s.n = cli::parse_shadow_size(value);
    } else if (kind == "mask") {
        if (item != "on" && item != "off") throw InputError(value.name + ": '" + item + "' is not on or off");
        s.on = item == "on";
    } else if (kind == "volumes") {
        if (item != "split" && item != "whole-target" && item != "one-variant" && item != "none")
            throw InputError(value.name + ": '" + item + "' is not split, whole-target, one-variant or none");
        s.suffix = item;
    } else if (kind == "depth") {
        s.n = cli::parse_max_depth(value);
    } else {
        std::tie(s.width, s.height) = cli::parse_eye_size(value);
    }
    return s;
}

}  // namespace

std::vector<SweepItem> parse_sweep(const std::string& sweep) {
    if (sweep.empty() || sweep == "techniques") return {};
    const size_t colon = sweep.find(':');
    const std::string kind = sweep.substr(0, colon);
    bool known = false;
    for (std::string_view k : kKinds) known = known || kind == k;
    if (colon == std::string::npos || !known || colon + 1 == sweep.size())
        throw InputError(
            "--sweep: '" + sweep +
            "' is not techniques, portals:N,..., boxes:N,..., depth:N,..., size:WxH,..., samples:N,..., "
            "lights:fixed|N|N/naive|N/one-part,..., light-depth:N,..., shadow-size:N,..., mask:on|off,... or "
            "volumes:split|whole-target|one-variant|none,...");
    std::vector<SweepItem> items;
    for (const std::string& item : split(sweep.substr(colon + 1), ',')) items.push_back(parse_item(kind, item));
    return items;
}

}  // namespace impossible::bench
