// Rooms' colours and hatching, lamps and moving props' paths on the plan;
// see plan_parts.hpp.
#include <algorithm>
#include <cmath>

#include "design/plan_parts.hpp"

namespace impossible::design {

namespace plan_parts {
namespace {

// Okabe and Ito's colours for colour-blind readers ("Color Universal
// Design", 2002), less black and the yellow that vanishes on white.
// Ordered so that neighbours in the file differ most: blue, orange,
// reddish purple, bluish green, vermillion, sky blue.
constexpr double kPalette[6][3] = {{0.000, 0.447, 0.698}, {0.902, 0.624, 0.000}, {0.800, 0.475, 0.655},
                                   {0.000, 0.620, 0.451}, {0.835, 0.369, 0.000}, {0.337, 0.706, 0.914}};

Rgba hue(int index, double s, double v, double a) {
    double h = 0.13 + 0.618034 * index;
    h = (h - std::floor(h)) * 6.0;
    const int k = static_cast<int>(h) % 6;
    const double f = h - std::floor(h), p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
    const double c[6][3] = {{v, t, p}, {q, v, p}, {p, v, t}, {p, q, v}, {t, p, v}, {v, p, q}};
    return {c[k][0], c[k][1], c[k][2], a};
}

}  // namespace

Rgba room_colour(int room, Tone tone) {
    if (room < 0 || room >= 6) {
        switch (tone) {
            case Tone::Fill: return hue(room, 0.6, 0.9, 0.16);
            case Tone::Line: return hue(room, 0.8, 0.6, 1.0);
            case Tone::Dark: return hue(room, 0.9, 0.35, 1.0);
            case Tone::Prop: return hue(room, 0.7, 0.5, 0.55);
        }
    }
    const double* c = kPalette[room];
    switch (tone) {
        case Tone::Fill: return {c[0], c[1], c[2], 0.16};
        case Tone::Line: return {c[0], c[1], c[2], 1.0};
        case Tone::Dark: return {0.6 * c[0], 0.6 * c[1], 0.6 * c[2], 1.0};
        case Tone::Prop: return {0.75 * c[0], 0.75 * c[1], 0.75 * c[2], 0.55};
    }
    return {};
}

double room_hatch_angle(int room) {
    static constexpr double kEighths[8] = {1, 3, 0, 2, 0.5, 2.5, 1.5, 3.5};  // quarter turns of 45°
    return kEighths[room % 8] * 0.25 * math::kPi;
}

PlanShape fill(const std::string& group, const std::string& name, math::Polygon2 points, Rgba colour) {
    PlanShape s;
    s.group = group, s.name = name, s.points = std::move(points), s.colour = colour;
    return s;
}

PlanShape stroke(const std::string& group, const std::string& name, math::Polygon2 points, Rgba colour, double width,
                 bool closed, bool dashed) {
    PlanShape s = fill(group, name, std::move(points), colour);
    s.kind = PlanShape::Kind::Stroke, s.width = width, s.closed = closed, s.dashed = dashed;
    return s;
}

void arrow(Drawing& d, const std::string& group, const std::string& name, glm::dvec2 from, glm::dvec2 to, Rgba c,
           double width, bool dashed) {
    const double length = glm::distance(from, to);
    if (length < 1e-6) return;
    const glm::dvec2 dir = (to - from) / length, side{-dir.y, dir.x};
    const double head = std::min(0.18, 0.6 * length);
    d.shapes.push_back(stroke(group, name, {from, to - dir * head}, c, width, false, dashed));
    d.shapes.push_back(
        fill(group, name, {to, to - dir * head + side * (0.45 * head), to - dir * head - side * (0.45 * head)}, c));
}

math::Polygon2 circle(glm::dvec2 c, double r) {
    math::Polygon2 out;
    for (int i = 0; i < 24; ++i)
        out.push_back(c + r * glm::dvec2(std::cos(i * math::kPi / 12), std::sin(i * math::kPi / 12)));
    return out;
}

void add_hatching(Drawing& d, const layout::Layout& layout, const Report& r) {
    if (layout.rooms.size() > kMaxHatchedRooms || layout.rooms.size() < 2) return;
    for (std::size_t i = 0; i < layout.rooms.size(); ++i) {
        const int h = static_cast<int>(i);
        Rgba c = room_colour(h, Tone::Line);
        c.a = 0.45;
        for (const auto& line : hatch_lines(r.floors[i], room_hatch_angle(h), 0.2))
            d.shapes.push_back(stroke("hatching", layout.rooms[i].id, {line[0], line[1]}, c, 0.012));
    }
}

// Each moving prop's anchor along its keys on the physical floor (its
// listed room's placement; the walk through doors keeps it continuous
// there), dashed, with an arrow at the last key and a dot at the first.
void add_motions(Drawing& d, const layout::Layout& layout, const Report& r) {
    for (std::size_t i = 0; i < layout.rooms.size(); ++i)
        for (std::size_t k = 0; k < layout.rooms[i].props.size(); ++k) {
            const layout::Prop& prop = layout.rooms[i].props[k];
            const layout::Motion& motion = layout::prop_motion(prop);
            if (motion.keys.empty()) continue;
            const math::dmat4& m = r.placement.rooms[i].to_physical;
            const glm::dvec3 anchor = layout::prop_anchor(prop);
            math::Polygon2 line;
            for (const layout::MotionKey& key : motion.keys) line.push_back(to_floor(m, anchor + key.offset));
            const std::string& id = layout::prop_id(prop);
            d.shapes.push_back(fill("motion", id, circle(line.front(), 0.05), kMotionColour));
            if (line.size() < 2) continue;
            if (motion.loop) line.push_back(line.front());
            std::size_t last = line.size() - 1, before = last;
            while (before > 0 && glm::distance(line[before - 1], line[last]) < 1e-6) --before;
            if (before == 0) continue;
            --before;
            math::Polygon2 body(line.begin(), line.begin() + static_cast<std::ptrdiff_t>(before + 1));
            if (body.size() >= 2) d.shapes.push_back(stroke("motion", id, body, kMotionColour, 0.025, false, true));
            arrow(d, "motion", id, line[before], line[last], kMotionColour, 0.025, true);
        }
}

// A lamp as a sun: an amber disc with a dark rim and eight rays; a spot
// light adds an arrow along its direction on the floor.
void add_lights(Drawing& d, const layout::Layout& layout, const Report& r) {
    for (std::size_t i = 0; i < layout.rooms.size(); ++i)
        for (const layout::Light& light : layout.rooms[i].lights) {
            const math::dmat4& m = r.placement.rooms[i].to_physical;
            const glm::dvec2 at = to_floor(m, light.position);
            const std::string& name = layout.rooms[i].id;
            d.shapes.push_back(fill("lights", name, circle(at, 0.09), kLampColour));
            d.shapes.push_back(stroke("lights", name, circle(at, 0.09), kLampEdge, 0.015, true));
            for (int k = 0; k < 8; ++k) {
                const glm::dvec2 u{std::cos(k * math::kPi / 4), std::sin(k * math::kPi / 4)};
                d.shapes.push_back(stroke("lights", name, {at + u * 0.12, at + u * 0.18}, kLampEdge, 0.015));
            }
            if (!light.spot) continue;
            const glm::dvec2 dir = to_floor(m, light.position + light.spot->direction) - at;
            if (glm::length(dir) > 1e-3)
                arrow(d, "lights", name, at, at + glm::normalize(dir) * 0.4, kLampEdge, 0.02, false);
        }
}

}  // namespace plan_parts

std::vector<std::array<glm::dvec2, 2>> hatch_lines(const math::Polygon2& poly, double angle, double spacing) {
    std::vector<std::array<glm::dvec2, 2>> out;
    if (poly.size() < 3 || !(spacing > 0.0)) return out;
    const glm::dvec2 along{std::cos(angle), std::sin(angle)}, across{-along.y, along.x};
    double lo = INFINITY, hi = -INFINITY;
    for (const glm::dvec2& p : poly) lo = std::min(lo, glm::dot(p, across)), hi = std::max(hi, glm::dot(p, across));
    std::vector<double> ts;
    for (double o = (std::floor(lo / spacing) + 0.5) * spacing; o < hi; o += spacing) {
        ts.clear();
        for (std::size_t e = 0, n = poly.size(); e < n; ++e) {
            const glm::dvec2 a = poly[e], b = poly[(e + 1) % n];
            const double da = glm::dot(a, across) - o, db = glm::dot(b, across) - o;
            if ((da < 0.0) == (db < 0.0)) continue;
            const glm::dvec2 x = a + (b - a) * (da / (da - db));
            ts.push_back(glm::dot(x, along));
        }
        std::sort(ts.begin(), ts.end());
        for (std::size_t k = 0; k + 1 < ts.size(); k += 2)
            if (ts[k + 1] - ts[k] > 1e-9) out.push_back({across * o + along * ts[k], across * o + along * ts[k + 1]});
    }
    return out;
}

}  // namespace impossible::design
