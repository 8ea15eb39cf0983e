// The plan's shapes; see plan.hpp.
#include "design/plan.hpp"

#include "design/plan_parts.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <variant>

namespace impossible::design {
namespace {

using namespace plan_parts;

void add_doors(Drawing& d, const layout::Layout& layout, const Report& r) {
    for (std::size_t i = 0; i < layout.portals.size(); ++i) {
        const layout::Portal& p = layout.portals[i];
        if (p.kind != layout::PortalKind::Door) continue;
        const math::dmat4& m = r.placement.rooms[p.room].to_physical;
        const Rgba c = room_colour(p.room, Tone::Line);
        const auto line = door_line(p, m);
        d.shapes.push_back(stroke("doors", p.id, {line[0], line[1]}, c, 0.07));
        const glm::dvec2 centre = 0.5 * (line[0] + line[1]);
        const glm::dvec2 n = to_floor(m, p.rect.center + p.rect.normal) - to_floor(m, p.rect.center);
        if (glm::length(n) > 1e-6) {
            const glm::dvec2 u = glm::normalize(n);
            arrow(d, "doors", p.id, centre + u * 0.3, centre - u * 0.15, c, 0.025, false);
        }
        const layout::Portal& t = layout.portals[p.target];
        const auto other = door_line(t, r.placement.rooms[t.room].to_physical);
        arrow(d, "doors", p.id, centre, 0.5 * (other[0] + other[1]), c, 0.02, true);
    }
}

// The floor line of a portal, and its unit normal on the floor (zero for a
// floor or ceiling portal).
struct FloorLine {
    std::array<glm::dvec2, 2> ends;
    glm::dvec2 normal{0.0};
};

FloorLine floor_line(const layout::Portal& p, const math::dmat4& m) {
    FloorLine out{door_line(p, m)};
    const glm::dvec2 n = to_floor(m, p.rect.center + p.rect.normal) - to_floor(m, p.rect.center);
    if (glm::length(n) > 1e-6) out.normal = glm::normalize(n);
    return out;
}

// Mirrors as a thick silver line with short ticks on the back (the side that
// does not reflect), as architects draw a mirror's backing.
void add_mirrors(Drawing& d, const layout::Layout& layout, const Report& r) {
    const Rgba silver{0.55, 0.62, 0.70, 1.0};
    for (const layout::Portal& p : layout.portals) {
        if (p.kind != layout::PortalKind::Mirror) continue;
        const FloorLine line = floor_line(p, r.placement.rooms[p.room].to_physical);
        d.shapes.push_back(stroke("mirrors", p.id, {line.ends[0], line.ends[1]}, silver, 0.06));
        const double length = glm::distance(line.ends[0], line.ends[1]);
        if (glm::length(line.normal) == 0.0 || length < 1e-6) continue;
        const int ticks = std::max(2, static_cast<int>(length / 0.15));
        for (int k = 0; k <= ticks; ++k) {
            const glm::dvec2 at = line.ends[0] + (line.ends[1] - line.ends[0]) * (double(k) / ticks);
            d.shapes.push_back(stroke("mirrors", p.id, {at, at - line.normal * 0.1}, silver, 0.015));
        }
    }
}

// Windows as two thin blue lines (a pane, as in architects' plans), with a
// dashed arrow to the partner window where it lies elsewhere on the floor.
void add_windows(Drawing& d, const layout::Layout& layout, const Report& r) {
    const Rgba glass{0.20, 0.55, 0.90, 1.0};
    for (const layout::Portal& p : layout.portals) {
        if (p.kind != layout::PortalKind::Window) continue;
        const FloorLine line = floor_line(p, r.placement.rooms[p.room].to_physical);
        const glm::dvec2 off = line.normal * 0.035;
        d.shapes.push_back(stroke("windows", p.id, {line.ends[0] + off, line.ends[1] + off}, glass, 0.02));
        d.shapes.push_back(stroke("windows", p.id, {line.ends[0] - off, line.ends[1] - off}, glass, 0.02));
        if (p.target < 0) continue;
        const layout::Portal& t = layout.portals[p.target];
        const auto other = door_line(t, r.placement.rooms[t.room].to_physical);
        arrow(d, "windows", p.id, 0.5 * (line.ends[0] + line.ends[1]), 0.5 * (other[0] + other[1]), glass, 0.015, true);
    }
}

// Labels sit at their room's centre, moved down 0.3 m at a time until none
// is closer than 0.25 m. Placed labels are that far apart, so a grid of
// 0.25 m cells holds a few each and a test looks at nine cells; a label
// still crowded after kMaxLabelMoves moves (rooms stacked on one spot) is
// left out: it would be drawn over the names already there, unreadable,
// and each name is dozens of rectangles in the PNG (10,000 rooms on one
// spot took 320 MB instead of 140). The legend still names the first rooms.
constexpr int kMaxLabelMoves = 32;

class LabelSpots {
public:
    std::optional<glm::dvec2> place(glm::dvec2 at) {
        for (int move = 0; move <= kMaxLabelMoves; ++move, at.y += 0.3) {
            if (crowded(at)) continue;
            cells_[key(cell(at.x), cell(at.y))].push_back(at);
            return at;
        }
        return std::nullopt;
    }

private:
    std::unordered_map<std::uint64_t, std::vector<glm::dvec2>> cells_;

    static std::int64_t cell(double v) { return static_cast<std::int64_t>(std::floor(v / 0.25)); }
    static std::uint64_t key(std::int64_t x, std::int64_t y) {
        return (static_cast<std::uint64_t>(x) << 32) ^ static_cast<std::uint64_t>(y & 0xffffffff);
    }
    bool crowded(glm::dvec2 at) const {
        const std::int64_t cx = cell(at.x), cy = cell(at.y);
        for (std::int64_t x = cx - 1; x <= cx + 1; ++x)
            for (std::int64_t y = cy - 1; y <= cy + 1; ++y) {
                const auto it = cells_.find(key(x, y));
                if (it == cells_.end()) continue;
                for (const glm::dvec2& u : it->second)
                    if (glm::distance(u, at) < 0.25) return true;
            }
        return false;
    }
};

// Where a floor's label goes: a box room's centre (the mean of its four
// corners), a polygon's centroid, or, where the centroid falls outside it (a
// bent corridor), the middle of its widest stretch along the centroid's z.
glm::dvec2 label_spot(const math::Polygon2& floor) {
    glm::dvec2 at{0.0};
    if (floor.size() == 4) {
        for (const glm::dvec2& p : floor) at += 0.25 * p;
        return at;
    }
    const double twice = 2.0 * math::signed_area(floor);
    if (floor.size() < 3 || twice == 0.0) return floor.empty() ? at : floor[0];
    for (std::size_t i = 0, n = floor.size(); i < n; ++i) {
        const glm::dvec2 a = floor[i], b = floor[(i + 1) % n];
        at += (a + b) * (a.x * b.y - b.x * a.y) / (3.0 * twice);
    }
    if (math::contains(floor, at)) return at;
    std::vector<double> xs;
    for (std::size_t i = 0, n = floor.size(); i < n; ++i) {
        const glm::dvec2 a = floor[i], b = floor[(i + 1) % n];
        if ((a.y <= at.y) != (b.y <= at.y)) xs.push_back(a.x + (at.y - a.y) / (b.y - a.y) * (b.x - a.x));
    }
    std::sort(xs.begin(), xs.end());
    double widest = -1.0;
    for (std::size_t k = 0; k + 1 < xs.size(); k += 2)
        if (xs[k + 1] - xs[k] > widest) widest = xs[k + 1] - xs[k], at.x = 0.5 * (xs[k] + xs[k + 1]);
    return at;
}

void add_labels(Drawing& d, const layout::Layout& layout, const Report& r) {
    LabelSpots spots;
    for (std::size_t i = 0; i < layout.rooms.size(); ++i) {
        const std::optional<glm::dvec2> at = spots.place(label_spot(r.floors[i]));
        if (!at) continue;
        PlanShape s = fill("labels", layout.rooms[i].id, {*at}, room_colour(static_cast<int>(i), Tone::Dark));
        s.kind = PlanShape::Kind::Text;
        s.text = layout.rooms[i].id + reach_note(layout, r, i, " (unreachable)");
        d.shapes.push_back(s);
    }
}

void add_floor(Drawing& d, const layout::Layout& layout, const Report& r) {
    if (layout.play_area) {
        const math::Polygon2 area = layout::outline(*layout.play_area);
        d.shapes.push_back(fill("play-area", "", area, {0.90, 0.95, 0.88, 1.0}));
        d.shapes.push_back(stroke("play-area", "", area, {0.15, 0.45, 0.2, 1.0}, 0.04, true));
    }
    for (std::size_t i = 0; i < layout.rooms.size(); ++i) {
        const bool reachable = r.placement.rooms[i].reachable || r.changes.after_change[i] >= 0;
        const int h = static_cast<int>(i);
        d.shapes.push_back(fill("rooms", layout.rooms[i].id, r.floors[i], room_colour(h, Tone::Fill)));
        d.shapes.push_back(
            stroke("rooms", layout.rooms[i].id, r.floors[i], room_colour(h, Tone::Line), 0.03, true, !reachable));
    }
    add_hatching(d, layout, r);
    for (const Overlap& o : r.overlaps) {
        // Light, so that several pairs stacked on one spot still show the rooms under them.
        const Rgba c = o.noticeable ? Rgba{0.85, 0.1, 0.1, 0.08} : Rgba{0.1, 0.1, 0.1, 0.08};
        for (const math::Polygon2& piece : o.shared)
            d.shapes.push_back(fill("overlaps", layout.rooms[o.a].id + "/" + layout.rooms[o.b].id, piece, c));
    }
    for (std::size_t i = 0; i < layout.rooms.size(); ++i)
        for (const layout::Prop& prop : layout.rooms[i].props)
            if (const auto* box = std::get_if<layout::BoxProp>(&prop)) {
                layout::Room footprint;
                footprint.min = box->min;
                footprint.max = box->max;
                d.shapes.push_back(fill("props", layout.rooms[i].id,
                                        physical_floor(footprint, r.placement.rooms[i].to_physical),
                                        room_colour(static_cast<int>(i), Tone::Prop)));
            }
}

}  // namespace

Drawing plan_drawing(const layout::Layout& layout, const Report& r, const std::vector<math::HeadPose>& path) {
    Drawing d;
    d.title = (layout.name.empty() ? layout.source : layout.name) + " - the physical floor (1 m grid)";
    bool any = false;
    auto grow = [&](glm::dvec2 p) {
        d.min = any ? glm::min(d.min, p) : p;
        d.max = any ? glm::max(d.max, p) : p;
        any = true;
    };
    if (layout.play_area)
        for (const glm::dvec2& p : layout::outline(*layout.play_area)) grow(p);
    for (const math::Polygon2& f : r.floors)
        for (const glm::dvec2& p : f) grow(p);
    for (const math::HeadPose& p : path) grow({p.position.x, p.position.z});
    d.min = glm::floor(d.min - 0.5), d.max = glm::ceil(d.max + 0.5);
    for (double x = d.min.x; x <= d.max.x + 1e-9; x += 1.0)
        d.shapes.push_back(stroke("grid", "", {{x, d.min.y}, {x, d.max.y}}, {0.8, 0.8, 0.8, 1.0}, 0.01));
    for (double z = d.min.y; z <= d.max.y + 1e-9; z += 1.0)
        d.shapes.push_back(stroke("grid", "", {{d.min.x, z}, {d.max.x, z}}, {0.8, 0.8, 0.8, 1.0}, 0.01));
    add_floor(d, layout, r);
    add_doors(d, layout, r);
    add_mirrors(d, layout, r);
    add_windows(d, layout, r);
    add_motions(d, layout, r);
    add_lights(d, layout, r);
    add_changes(d, layout, r);
    const glm::dvec2 s{layout.start.position.x, layout.start.position.z};
    const double yaw = math::radians(layout.start.yaw_deg);
    d.shapes.push_back(fill("start", "start", circle(s, 0.12), {0.85, 0.1, 0.1, 1.0}));
    arrow(d, "start", "start", s, s + 0.45 * glm::dvec2(-std::sin(yaw), -std::cos(yaw)), {0.85, 0.1, 0.1, 1.0}, 0.035,
          false);
    if (!path.empty()) {
        math::Polygon2 line;
        for (const math::HeadPose& p : path) line.push_back({p.position.x, p.position.z});
        d.shapes.push_back(stroke("path", "walk", line, {0.1, 0.25, 0.85, 0.85}, 0.03));
    }
    add_labels(d, layout, r);
    add_legend(d, layout, r, !path.empty());
    return d;
}

double plan_scale(const Drawing& d, int max_pixels) {
    const glm::dvec2 extent = d.max - d.min;
    return std::min(100.0, max_pixels / std::max({extent.x, extent.y, 1.0}));
}

}  // namespace impossible::design
