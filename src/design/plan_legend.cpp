// The plan's legend and title, in pixels below and above the floor; see
// plan.hpp (plan_overlay) and plan_parts.hpp (add_legend).
#include <algorithm>
#include <cmath>

#include "design/plan_parts.hpp"
#include "design/plan_pieces.hpp"
#include "image/text_rects.hpp"

namespace impossible::design {

namespace {

using namespace plan_parts;

constexpr double kTitlePixels = 14.0;
constexpr double kLegendPixels = 12.0;  // the legend's text
constexpr double kRowHeight = 20.0;
constexpr double kMargin = 8.0;
constexpr double kSampleWidth = 22.0, kSampleHeight = 12.0;
constexpr Rgba kInk{0.2, 0.2, 0.2, 1.0};

// Text of `pixels` font size is this wide (the segment font, as the PNG draws it).
double text_pixels(const std::string& text, double pixels) { return image::text_width(text) * pixels / 10.0; }

double entry_width(const LegendEntry& e) { return kSampleWidth + 6.0 + text_pixels(e.text, kLegendPixels) + 16.0; }

// Where each entry goes: its left edge and row, filling rows left to right.
struct Placed {
    double x = 0.0;
    int row = 0;
};

std::vector<Placed> place_entries(const Drawing& d, double width) {
    std::vector<Placed> out;
    double x = kMargin;
    int row = 0;
    for (const LegendEntry& e : d.legend) {
        const double w = entry_width(e);
        if (x > kMargin && x + w > width - kMargin) x = kMargin, ++row;
        out.push_back({x, row});
        x += w;
    }
    return out;
}

PlanShape text_shape(const std::string& group, const std::string& text, glm::dvec2 at, double pixels, Rgba c) {
    PlanShape s = fill(group, "", {at}, c);
    s.kind = PlanShape::Kind::Text, s.text = text, s.size = pixels, s.centred = false;
    return s;
}

void add_sample(std::vector<PlanShape>& out, const LegendEntry& e, glm::dvec2 at) {
    const glm::dvec2 lo = at, hi = at + glm::dvec2(kSampleWidth, kSampleHeight);
    const double mid = 0.5 * (lo.y + hi.y);
    switch (e.sample) {
        case LegendEntry::Sample::Swatch: {
            const math::Polygon2 box = {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
            out.push_back(fill("legend", "", box, e.fill));
            if (e.hatch >= 0.0) {
                Rgba c = e.line;
                c.a = 0.45;
                for (const auto& l : hatch_lines(box, e.hatch, 4.0))
                    out.push_back(stroke("legend", "", {l[0], l[1]}, c, 1.0));
            }
            out.push_back(stroke("legend", "", box, e.line, 1.5, true));
            break;
        }
        case LegendEntry::Sample::Line:
        case LegendEntry::Sample::Dashed:
            out.push_back(stroke("legend", "", {{lo.x, mid}, {hi.x, mid}}, e.line, 3.0, false,
                                 e.sample == LegendEntry::Sample::Dashed));
            break;
        case LegendEntry::Sample::Dot: out.push_back(fill("legend", "", circle({lo.x + 6.0, mid}, 5.0), e.line)); break;
    }
}

}  // namespace

PlanSize plan_size(const Drawing& d, double k) {
    PlanSize s;
    s.width = static_cast<int>(std::ceil((d.max.x - d.min.x) * k));
    s.floor_top = kPlanTitle;
    s.legend_top = kPlanTitle + (d.max.y - d.min.y) * k + 6.0;
    const std::vector<Placed> placed = place_entries(d, s.width);
    const double legend = placed.empty() ? 0.0 : (placed.back().row + 1) * kRowHeight + 4.0;
    s.height = static_cast<int>(std::ceil(s.legend_top + legend));
    return s;
}

std::vector<PlanShape> plan_overlay(const Drawing& d, double k) {
    std::vector<PlanShape> out;
    out.push_back(text_shape("title", d.title, {kMargin, 19.0}, kTitlePixels, kInk));
    const PlanSize size = plan_size(d, k);
    const std::vector<Placed> placed = place_entries(d, size.width);
    for (std::size_t i = 0; i < d.legend.size(); ++i) {
        const LegendEntry& e = d.legend[i];
        const double top = size.legend_top + placed[i].row * kRowHeight;
        add_sample(out, e, {placed[i].x, top + 0.5 * (kRowHeight - kSampleHeight)});
        const double baseline = top + 0.5 * kRowHeight + 0.35 * kLegendPixels;
        out.push_back(text_shape("legend", e.text, {placed[i].x + kSampleWidth + 6.0, baseline}, kLegendPixels, kInk));
    }
    return out;
}

double label_pixels(const PlanShape& text, double k) { return std::max(9.0, text.size * k); }

namespace plan_parts {

void add_legend(Drawing& d, const layout::Layout& layout, const Report& r, bool path) {
    using Sample = LegendEntry::Sample;
    const bool hatched = layout.rooms.size() >= 2 && layout.rooms.size() <= kMaxHatchedRooms;
    const std::size_t rooms = std::min(layout.rooms.size(), kMaxLegendRooms);
    for (std::size_t i = 0; i < rooms; ++i) {
        const int h = static_cast<int>(i);
        d.legend.push_back({Sample::Swatch, room_colour(h, Tone::Fill), room_colour(h, Tone::Line),
                            hatched ? room_hatch_angle(h) : -1.0,
                            layout.rooms[i].id + reach_note(layout, r, i, " (unreachable, dashed)")});
    }
    if (layout.rooms.size() > rooms)
        d.legend.push_back({Sample::Swatch,
                            {1, 1, 1, 1},
                            {0.6, 0.6, 0.6, 1},
                            -1.0,
                            "... and " + std::to_string(layout.rooms.size() - rooms) + " more rooms"});
    const auto has = [&](const char* group) {
        return std::any_of(d.shapes.begin(), d.shapes.end(), [&](const PlanShape& s) { return s.group == group; });
    };
    if (layout.play_area) d.legend.push_back({Sample::Line, {}, {0.15, 0.45, 0.2, 1.0}, -1.0, "play area"});
    const bool noticed =
        std::any_of(r.overlaps.begin(), r.overlaps.end(), [](const Overlap& o) { return o.noticeable; });
    if (!r.overlaps.empty())
        d.legend.push_back({Sample::Swatch, {0.1, 0.1, 0.1, 0.2}, {0.5, 0.5, 0.5, 1.0}, -1.0, "shared floor"});
    if (noticed)
        d.legend.push_back(
            {Sample::Swatch, {0.85, 0.1, 0.1, 0.25}, {0.85, 0.1, 0.1, 1.0}, -1.0, "shared floor likely noticed"});
    if (has("props")) d.legend.push_back({Sample::Swatch, {0.4, 0.4, 0.4, 0.55}, {0.4, 0.4, 0.4, 0.55}, -1.0, "prop"});
    if (has("doors"))
        d.legend.push_back(
            {Sample::Line, {}, {0.3, 0.3, 0.3, 1.0}, -1.0, "door (arrow: the way through; dashed: to its partner)"});
    if (has("mirrors")) d.legend.push_back({Sample::Line, {}, {0.55, 0.62, 0.70, 1.0}, -1.0, "mirror"});
    if (has("windows")) d.legend.push_back({Sample::Line, {}, {0.20, 0.55, 0.90, 1.0}, -1.0, "window"});
    if (has("motion")) d.legend.push_back({Sample::Dashed, {}, kMotionColour, -1.0, "moving prop's path"});
    if (has("lights")) d.legend.push_back({Sample::Dot, {}, kLampColour, -1.0, "lamp"});
    if (has("changes"))
        d.legend.push_back({Sample::Dashed, {}, kChangeColour, -1.0, "a change's new pair (labelled with its id)"});
    d.legend.push_back({Sample::Dot, {}, {0.85, 0.1, 0.1, 1.0}, -1.0, "start"});
    if (path) d.legend.push_back({Sample::Line, {}, {0.1, 0.25, 0.85, 0.85}, -1.0, "walk"});
}

}  // namespace plan_parts

}  // namespace impossible::design
