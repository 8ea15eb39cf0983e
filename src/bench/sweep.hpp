// bench's --sweep KIND:ITEM,...: each item parsed when the options are read,
// before any layout is loaded, by the frame's option rows' parsers
// (cli/frame_options.hpp) where the kind is an option of render, with
// messages naming "--sweep KIND".
#pragma once

#include <string>
#include <vector>

namespace impossible::bench {

struct SweepItem {
    std::string kind;           // "samples"
    std::string name;           // "samples=4", the configuration's name
    int n = 0;                  // the count, depth, samples or size; lights: -1 for "fixed"
    int width = 0, height = 0;  // size
    std::string
        suffix;  // "all", "separate", "all-faces" (boxes), "all-steps" (portals), "naive" (lights); volumes: the item
    bool on = false;  // mask
};

// "" and "techniques" give none; throws InputError for an unknown kind or a
// bad item.
std::vector<SweepItem> parse_sweep(const std::string& sweep);

}  // namespace impossible::bench
