// The layout generator; see generate.hpp.
#include "design/generate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "base/format.hpp"
#include "design/pack_search.hpp"
#include "design/splitmix.hpp"
#include "design/widest_spot.hpp"
#include "layout/layout.hpp"
#include "layout/limits.hpp"

namespace impossible::design {
namespace {

std::string metres(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", v);
    return text;
}

// Where the play area is widest, for the messages of a play area where the
// rooms do not fit: what is the obstacle there, however large the floor
// (a star 1000 m across whose core is 1.4 m wide).
std::string widest_spot_text(const math::Polygon2& area, std::optional<WidestSpot>& spot) {
    if (!spot) spot = widest_spot(area, AreaIndex(area));
    auto cm = [](double v) { return format_number(std::round(v * 100) / 100); };  // to the precision
    return std::string(spot->complete ? "its widest spot is" : "the widest spot found is") + " a circle " +
           cm(2 * spot->radius) + " m across at (" + cm(spot->centre.x) + ", " + cm(spot->centre.y) + ")";
}

// Why no room fits, when none does: the play area is narrower than a room
// (`packed`: whether N rooms were tried and did not fit).
std::optional<std::string> too_narrow(const GenerateOptions& o, bool packed, std::optional<WidestSpot>& spot) {
    glm::dvec2 lo = o.play_area[0], hi = lo;
    for (const glm::dvec2& p : o.play_area) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const std::string size = metres(hi.x - lo.x) + " x " + metres(hi.y - lo.y) + " m";
    if (std::min(hi.x - lo.x, hi.y - lo.y) < kRoomMinWidth + 0.02)
        return "a room cannot be " + metres(kRoomMinWidth) + " m wide on a " + size + " floor (it needs " +
               metres(kRoomMinWidth + 0.02) + " m across)";
    if (!packed) return std::nullopt;
    GenerateOptions one = o;
    one.rooms = 1;
    if (o.rooms > 1 && (pack_rooms({o.play_area, 1, o.seed, std::nullopt}) || grow_boxes(one, spot)))
        return std::nullopt;
    return "no room " + metres(kRoomMinWidth) + " m wide fits in this play area (" + size + " across; " +
           widest_spot_text(o.play_area, spot) + ")";
}

// The loader's limits on a play area (layout/limits.hpp): what a layout's
// play_area may hold, so that the layout written loads.
std::optional<std::string> play_area_problem(const math::Polygon2& area) {
    namespace lim = layout::limits;
    if (area.size() > lim::kMaxPlayAreaCorners)
        return "the play area has " + std::to_string(area.size()) + " corners; a layout's may have at most " +
               std::to_string(lim::kMaxPlayAreaCorners);
    for (std::size_t i = 0; i < area.size(); ++i)
        for (double v : {area[i].x, area[i].y})
            if (!std::isfinite(v) || std::abs(v) > lim::kMaxCoordinate)
                return "the play area's corner " + std::to_string(i) + " (" + format_number(area[i].x) + ", " +
                       format_number(area[i].y) + ") is not a coordinate within +-" +
                       format_number(lim::kMaxCoordinate) + " m";
    if (const auto problem = math::simple_polygon_problem(area))
        return "the play area must be a simple polygon: " + problem->message;
    return std::nullopt;
}

// The layout written must pass the loader's own checks: a generator defect
// is an error here, never a file that `validate` refuses.
std::optional<std::string> load_problem(const std::string& text) {
    const layout::LoadResult loaded = layout::load_layout_text(text, "<generated layout>", ".");
    if (loaded.errors.empty()) return std::nullopt;
    return "the generated layout does not pass the loader's checks (a defect of generate; please report it): " +
           loaded.errors.front().str();
}

}  // namespace

// In generate_json.cpp: the packing as layout JSON text.
std::string layout_text(const GenerateOptions& o, const Packing& p, const std::vector<int>& heights,
                        std::uint64_t prop_seed);

Result<Generated> generate(const GenerateOptions& o) {
    if (o.rooms < 1 || o.rooms > kMaxGeneratedRooms)
        return Error{"--rooms must be 1.." + std::to_string(kMaxGeneratedRooms)};
    if (const auto problem = play_area_problem(o.play_area)) return Error{*problem};
    std::optional<WidestSpot> spot;
    if (const auto why = too_narrow(o, false, spot)) return Error{*why};
    std::optional<Packing> p = pack_rooms({o.play_area, o.rooms, o.seed, o.max_overlap});
    if (!p) p = grow_boxes(o, spot);
    if (!p)
        if (const auto why = too_narrow(o, true, spot)) return Error{*why};
    if (!p)
        return Error{"could not fit " + std::to_string(o.rooms) + " rooms of at least " + metres(kRoomMinWidth) +
                     " m, joined by doors, in this play area within the overlap limit (" +
                     widest_spot_text(o.play_area, spot) +
                     "; try fewer rooms, a larger floor or a higher --max-overlap)"};
    SplitMix rng{o.seed * 0xD1B54A32D192ED03ull + 7};
    std::vector<int> heights;
    for (std::size_t i = 0; i < p->rooms.size(); ++i) heights.push_back(rng.uniform(26, 32));
    Generated g;
    g.rooms = static_cast<int>(p->rooms.size());
    g.floor_area = p->floor_area;
    g.play_area = math::area(o.play_area);
    g.expansion_ratio = g.floor_area / g.play_area;
    g.text = layout_text(o, *p, heights, rng.next());
    if (const auto problem = load_problem(g.text)) return Error{*problem};
    return g;
}

Result<std::string> generate_layout(const GenerateOptions& o) {
    Result<Generated> g = generate(o);
    if (!g) return Error{g.error()};
    return std::move(g->text);
}

}  // namespace impossible::design
