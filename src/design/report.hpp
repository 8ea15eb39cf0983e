// The designer's report of `impossible validate` (cli.md, "Designer
// commands"): besides the summary, where each room lies on the physical
// floor, which rooms overlap and by how much (design/overlap.hpp), which
// rooms no door leads to from the start, and which rooms and doors reach
// outside the play area there. Every finding is a warning: the layout is
// valid, but a walker would notice or could not get there.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>  // the report as JSON: include <nlohmann/json.hpp> to use it

#include "design/obstacles.hpp"
#include "design/overlap.hpp"
#include "design/placement.hpp"
#include "design/report_changes.hpp"
#include "layout/layout.hpp"
#include "lights/light_bound.hpp"
#include "lights/light_images.hpp"

namespace impossible::design {

struct RoomFinding {
    int room = -1;
    double outside_area = 0.0;  // m² of its physical floor outside the play area
};

struct Report {
    layout::Summary summary;
    Placement placement;
    std::vector<math::Polygon2> floors;  // physical floor of each room
    std::vector<Overlap> overlaps;       // the listed pairs, at most kMaxListedOverlaps (design/overlap.hpp)
    std::size_t overlap_pairs = 0;       // pairs found, the listed included
    bool overlaps_exact = true;          // false: the search stopped at its limit; overlap_pairs is a lower bound
    // Rooms no door leads to from the start, file order, with every change
    // that can happen made (design/report_changes.hpp): a room reachable
    // only after a change is reachable.
    std::vector<int> unreachable;
    ChangesReach changes;                    // what the layout's changes make reachable (empty without changes)
    std::vector<RoomFinding> rooms_outside;  // with a play area: physical floors not inside it
    std::vector<int> doors_outside;          // portals whose floor line is not inside the play area
    // Doors a prop stands in the way of (design/obstacles.hpp), in portal
    // order, and for each the reachable rooms whose way from the start
    // passes it (or its partner) first: `tour` cannot walk to them.
    std::vector<BlockedDoor> blocked;
    std::vector<std::vector<int>> behind_blocked;
    std::vector<std::string> findings;  // one line each, for people
    // Under "lighting": "lights" only (empty for "fixed"): each room's lights
    // (its glTF props' included) and light paths, the light images that may
    // light it at the layout's light_depth (lights/light_images.hpp).
    std::vector<int> room_lights;
    std::vector<int> room_light_paths;
    // The light depth the paths were counted at: the layout's, or where the
    // rooms together would have more than kMaxReportedLightPaths paths or
    // lights::kMaxLightRects path rectangles, the deepest that stays within
    // (lights::light_bound), and what lowered it. Where even depth 0 has
    // more rectangles, frames are lit by only `lit_lights` of the `lights`
    // and the paths counted are theirs.
    int light_paths_depth = 0;
    lights::LightCut light_cut = lights::LightCut::None;
    std::size_t lit_lights = 0;
    std::size_t lights = 0;
};

// validate counts the light paths frames are lit by: at most this many, all
// rooms together, as the rasteriser and the tracer (docs/bounded-work.md): a
// 2 m cube of six windows has 1.6 million at light depth 8 and more, 5 GB
// and 26 s to list, and is lit at light depth 2 (133 paths).
inline constexpr std::size_t kMaxReportedLightPaths = lights::kMaxLightPaths;

Report make_report(const layout::Layout& layout);

// Whether there are (or may be) more overlapping pairs than the report lists.
inline bool overlaps_truncated(const Report& r) { return !r.overlaps_exact || r.overlap_pairs > r.overlaps.size(); }

// The lines `validate` prints after the summary.
std::string report_text(const layout::Layout& layout, const Report& report);

// The whole report as one JSON document; `warnings` are the loader's.
nlohmann::ordered_json report_json(const layout::Layout& layout, const Report& report,
                                   const std::vector<layout::Diagnostic>& warnings);

// A list of problems as JSON, for `validate --json` on an invalid layout.
nlohmann::ordered_json errors_json(const std::string& file, const std::vector<layout::Diagnostic>& errors);

}  // namespace impossible::design
