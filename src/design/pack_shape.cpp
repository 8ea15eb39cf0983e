// The packer's rooms and their geometry; see pack_shape.hpp.
#include "design/pack_shape.hpp"

#include <algorithm>
#include <cmath>

#include "math/conventions.hpp"

namespace impossible::design {
namespace {

double millimetres(double v) { return std::round(v * 1000.0) / 1000.0 + 0.0; }  // + 0.0: no -0

glm::dvec2 mm_rounded(glm::dvec2 p) { return {millimetres(p.x), millimetres(p.y)}; }

double cross2(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

// The L in canonical (s, t): body [0, A] x [0, B], arm [0, aw] x [B, B + len],
// mapped to the frame's (U, V) by the arm's side and end.
glm::dvec2 l_frame_point(const Shape& s, double cs, double ct) {
    switch (s.arm_side) {
        case 0: return {s.arm_high ? s.u1 - cs : s.u0 + cs, s.v0 + ct};
        case 1: return {s.arm_high ? s.u1 - cs : s.u0 + cs, s.v1 - ct};
        case 2: return {s.u0 + ct, s.arm_high ? s.v1 - cs : s.v0 + cs};
        default: return {s.u1 - ct, s.arm_high ? s.v1 - cs : s.v0 + cs};
    }
}

glm::dvec2 frame_to_floor(double angle, glm::dvec2 uv) {
    const double c = std::cos(angle), s = std::sin(angle);
    return mm_rounded({uv.x * c - uv.y * s, uv.x * s + uv.y * c});
}

math::Polygon2 frame_rect(double angle, double u0, double u1, double v0, double v1) {
    return {frame_to_floor(angle, {u0, v0}), frame_to_floor(angle, {u1, v0}), frame_to_floor(angle, {u1, v1}),
            frame_to_floor(angle, {u0, v1})};
}

void counter_clockwise(math::Polygon2& p) {
    if (math::signed_area(p) < 0.0) std::reverse(p.begin(), p.end());
}

// The L's outline, and two convex pieces that share its corners (so that
// they tile the rounded outline exactly): the body side up to the inner
// corner, and the arm side from the first corner through the inner corner.
RoomGeom l_geom(const Shape& s) {
    const bool along_u = s.arm_side < 2;
    const double A = along_u ? s.u1 - s.u0 : s.v1 - s.v0, B = along_u ? s.v1 - s.v0 : s.u1 - s.u0;
    const double aw = s.arm_width, top = B + s.arm_length;
    const double canon[6][2] = {{0, 0}, {A, 0}, {A, B}, {aw, B}, {aw, top}, {0, top}};
    math::Polygon2 p;
    for (const auto& c : canon) p.push_back(frame_to_floor(s.angle, l_frame_point(s, c[0], c[1])));
    RoomGeom g;
    g.outline = p;
    g.pieces = {{p[0], p[1], p[2], p[3]}, {p[0], p[3], p[4], p[5]}};
    counter_clockwise(g.outline);
    for (math::Polygon2& piece : g.pieces) counter_clockwise(piece);
    return g;
}

int arc_walls(const Shape& s) {
    return std::max(1, static_cast<int>(std::ceil((s.a1 - s.a0) / (kArcWallDegrees * math::kPi / 180.0) - 1e-9)));
}

RoomGeom arc_geom(const Shape& s) {
    const int n = arc_walls(s);
    std::vector<glm::dvec2> outer, inner;
    for (int k = 0; k <= n; ++k) {
        const double a = s.a0 + (s.a1 - s.a0) * k / n;
        const glm::dvec2 dir(std::cos(a), std::sin(a));
        outer.push_back(mm_rounded(s.centre + s.r1 * dir));
        inner.push_back(mm_rounded(s.centre + s.r0 * dir));
    }
    RoomGeom g;
    g.outline = outer;
    for (int k = n; k >= 0; --k) g.outline.push_back(inner[k]);
    for (int k = 0; k < n; ++k) g.pieces.push_back({inner[k], outer[k], outer[k + 1], inner[k + 1]});
    counter_clockwise(g.outline);
    for (math::Polygon2& p : g.pieces) counter_clockwise(p);
    return g;
}

void bounds(const math::Polygon2& p, glm::dvec2& lo, glm::dvec2& hi) {
    lo = hi = p[0];
    for (const glm::dvec2& q : p) lo = glm::min(lo, q), hi = glm::max(hi, q);
}

bool boxes_meet(glm::dvec2 alo, glm::dvec2 ahi, glm::dvec2 blo, glm::dvec2 bhi) {
    return alo.x < bhi.x && blo.x < ahi.x && alo.y < bhi.y && blo.y < ahi.y;
}

std::vector<Interval> intersect(const std::vector<Interval>& a, const std::vector<Interval>& b) {
    std::vector<Interval> out;
    std::size_t i = 0, j = 0;
    while (i < a.size() && j < b.size()) {
        const double lo = std::max(a[i].lo, b[j].lo), hi = std::min(a[i].hi, b[j].hi);
        if (lo <= hi) out.push_back({lo, hi});
        (a[i].hi < b[j].hi) ? ++i : ++j;
    }
    return out;
}

std::vector<Interval> shrunk(const std::vector<Interval>& a, double lo_by, double hi_by) {
    std::vector<Interval> out;
    for (const Interval& v : a)
        if (v.lo + lo_by <= v.hi - hi_by) out.push_back({v.lo + lo_by, v.hi - hi_by});
    return out;
}

// Where a door's centre may go along a line of `to` that it stands across:
// kDoorPassage free on one side, 0.05 m on the other.
std::vector<Interval> passage(const std::vector<Interval>& along, double half) {
    std::vector<Interval> out;
    for (const Interval& v : along) {
        const Interval a{v.lo + 0.05 + half, v.hi - kDoorPassage - half};
        const Interval b{v.lo + kDoorPassage + half, v.hi - 0.05 - half};
        if (a.lo <= a.hi && b.lo <= b.hi && b.lo <= a.hi) {
            out.push_back({a.lo, b.hi});
        } else {
            if (a.lo <= a.hi) out.push_back(a);
            if (b.lo <= b.hi) out.push_back(b);
        }
    }
    return out;
}

}  // namespace

RoomGeom room_geom(const Shape& s) {
    RoomGeom g;
    if (s.kind == Shape::Kind::L && s.arm_width > 0.0 && s.arm_length > 0.0) {
        g = l_geom(s);
    } else if (s.kind == Shape::Kind::Arc) {
        g = arc_geom(s);
    } else {
        g.outline = frame_rect(s.angle, s.u0, s.u1, s.v0, s.v1);
        g.pieces = {g.outline};
        g.box = s.angle == 0.0;
    }
    g.area = math::area(g.outline);
    bounds(g.outline, g.lo, g.hi);
    return g;
}

double shape_width(const Shape& s) {
    if (s.kind == Shape::Kind::Arc) return s.r1 * std::cos((s.a1 - s.a0) / arc_walls(s) / 2) - s.r0;
    const double body = std::min(s.u1 - s.u0, s.v1 - s.v0);
    if (s.kind == Shape::Kind::L && s.arm_length > 0.0) return std::min(body, s.arm_width);
    return body;
}

double shared_area(const RoomGeom& a, const RoomGeom& b) {
    if (!boxes_meet(a.lo, a.hi, b.lo, b.hi)) return 0.0;
    double sum = 0.0;
    for (const math::Polygon2& p : a.pieces)
        for (const math::Polygon2& q : b.pieces) sum += math::intersection_area(p, q);
    return sum;
}

bool inside_area(const RoomGeom& room, const math::Polygon2& area) {
    for (const math::Polygon2& p : room.pieces)
        if (!math::convex_inside(p, area)) return false;
    return true;
}

std::vector<Interval> line_inside(const math::Polygon2& outline, glm::dvec2 p, glm::dvec2 d) {
    std::vector<double> ts;
    for (std::size_t i = 0, n = outline.size(); i < n; ++i) {
        const glm::dvec2 c = outline[i], e = outline[(i + 1) % n];
        const double sc = cross2(d, c - p), se = cross2(d, e - p);
        if ((sc > 0.0) == (se > 0.0)) continue;
        const glm::dvec2 hit = c + (e - c) * (sc / (sc - se));
        ts.push_back(glm::dot(hit - p, d));
    }
    std::sort(ts.begin(), ts.end());
    std::vector<Interval> out;
    for (std::size_t i = 0; i + 1 < ts.size(); i += 2) out.push_back({ts[i], ts[i + 1]});
    return out;
}

std::vector<Interval> door_stretches(const RoomGeom& from, int wall, const RoomGeom& to) {
    const std::size_t n = from.outline.size();
    const glm::dvec2 a = from.outline[wall], b = from.outline[(wall + 1) % n];
    const double length = glm::distance(a, b), half = kPackDoorWidth / 2;
    if (length < kPackDoorWidth + 0.2) return {};
    glm::dvec2 lo = glm::min(a, b) - glm::dvec2(kDoorReach), hi = glm::max(a, b) + glm::dvec2(kDoorReach);
    if (!boxes_meet(lo, hi, to.lo, to.hi)) return {};
    const glm::dvec2 d = (b - a) / length, in(-d.y, d.x);
    std::vector<Interval> ok{{0.1 + half, length - 0.1 - half}};
    for (const double off : {0.05, 0.5})
        ok = intersect(ok, shrunk(line_inside(from.outline, a + in * off, d), half, half));
    for (const double off : {0.02, kDoorReach / 2, kDoorReach}) {
        if (ok.empty()) return ok;
        ok = intersect(ok, shrunk(line_inside(to.outline, a - in * off, d), half, half));
    }
    if (ok.empty()) return ok;
    return intersect(ok, passage(line_inside(to.outline, a - in * 0.001, d), half));
}

bool door_possible(const RoomGeom& from, const RoomGeom& to) {
    if (!boxes_meet(from.lo - glm::dvec2(kDoorReach), from.hi + glm::dvec2(kDoorReach), to.lo, to.hi)) return false;
    for (int w = 0, n = static_cast<int>(from.outline.size()); w < n; ++w)
        if (!door_stretches(from, w, to).empty()) return true;
    return false;
}

}  // namespace impossible::design
