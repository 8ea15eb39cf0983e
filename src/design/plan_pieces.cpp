// The plan's shapes as polygons in canvas pixels; see plan_pieces.hpp.
#include "design/plan_pieces.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "image/text_rects.hpp"

namespace impossible::design {
namespace {

math::Polygon2 disc(glm::dvec2 c, double r) {
    math::Polygon2 out;
    for (int i = 0; i < 16; ++i)
        out.push_back(c + r * glm::dvec2(std::cos(i * math::kPi / 8), std::sin(i * math::kPi / 8)));
    return out;
}

Piece piece_of(const Rgba& c, RowRange rows) {
    Piece p;
    p.r = static_cast<float>(c.r), p.g = static_cast<float>(c.g), p.b = static_cast<float>(c.b);
    p.a = static_cast<float>(c.a);
    p.rows = rows;
    return p;
}

void add_polygon(Pieces& out, const math::Polygon2& poly, const Rgba& c, int height) {
    Piece p = piece_of(c, polygon_rows(poly.data(), poly.size(), height));
    if (p.rows.first > p.rows.last) return;  // covers no row
    p.first = out.points.size(), p.count = poly.size();
    out.points.insert(out.points.end(), poly.begin(), poly.end());
    out.list.push_back(p);
}

void add_run(Pieces& out, DashRun run, const Rgba& c, int height) {
    double top = INFINITY, bottom = -INFINITY;
    glm::dvec2 corners[4];
    for (std::size_t k = 0; k < run.starts.size(); ++k) {
        run.quad(k, corners);
        for (const glm::dvec2& p : corners) top = std::min(top, p.y), bottom = std::max(bottom, p.y);
    }
    const glm::dvec2 extent[3] = {{0.0, top}, {0.0, bottom}, {0.0, top}};
    Piece p = piece_of(c, polygon_rows(extent, 3, height));
    if (p.rows.first > p.rows.last) return;
    p.run = true, p.first = out.runs.size();
    out.runs.push_back(std::move(run));
    out.list.push_back(p);
}

// A stroke as polygons: segments (dashed ones cut into dashes) and joins.
// Opaque strokes get round joins; translucent ones none, so nothing is
// blended twice where pieces meet (they overlap at most at the joins).
void add_stroke(Pieces& out, const PlanShape& s, double k, double dash_on, double dash_off, int height) {
    const double half = std::max(0.5 * kPlanSuper, 0.5 * s.width * k);
    std::vector<glm::dvec2> pts = s.points;
    if (s.closed && !pts.empty()) pts.push_back(pts.front());
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
        const glm::dvec2 a = pts[i], b = pts[i + 1];
        const double length = glm::distance(a, b);
        if (length < 1e-9) continue;
        const glm::dvec2 dir = (b - a) / length, side = glm::dvec2(-dir.y, dir.x) * half;
        if (s.dashed) {
            DashRun run{a, dir, side, length, dash_on, {}};
            for (double t = 0.0; t < length; t += dash_on + dash_off) run.starts.push_back(t);
            add_run(out, std::move(run), s.colour, height);
        } else {
            const glm::dvec2 p = a + dir * 0.0, q = a + dir * std::min(length, 0.0 + length);
            add_polygon(out, {p + side, q + side, q - side, p - side}, s.colour, height);
        }
        if (s.colour.a >= 1.0 && half > kPlanSuper) add_polygon(out, disc(b, half), s.colour, height);
    }
}

// A line of text, its baseline at `at` (canvas pixels), `pixels` its font
// size: the segment font's rectangles (image/text_rects.hpp).
void add_text(Pieces& out, const PlanShape& s, glm::dvec2 at, double pixels, int height) {
    const double scale = pixels / 10.0;  // a capital, 7 units, is 0.7 of the font size
    const double width = std::max(0.0, static_cast<double>(image::text_width(s.text)) - 1.0) * scale;
    const glm::dvec2 origin{s.centred ? at.x - 0.5 * width : at.x, at.y - image::kTextBaseline * scale};
    for (const image::TextRect& r : image::text_rects(s.text)) {
        const glm::dvec2 lo = origin + glm::dvec2(r.x0, r.y0) * scale, hi = origin + glm::dvec2(r.x1, r.y1) * scale;
        add_polygon(out, {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}}, s.colour, height);
    }
}

}  // namespace

void DashRun::quad(std::size_t k, glm::dvec2* corners) const {
    const double t = starts[k];
    const glm::dvec2 p = a + dir * t, q = a + dir * std::min(length, t + on);
    corners[0] = p + side, corners[1] = q + side, corners[2] = q - side, corners[3] = p - side;
}

DashRun::Cursor DashRun::start() const { return dir.y >= 0.0 ? Cursor{0, 0} : Cursor{starts.size(), starts.size()}; }

void DashRun::spans(int y, int width, Cursor& near, std::vector<Span>& out) const {
    // The dashes lie in order along the segment, so their rows rise or fall
    // with k, and the dashes within 0.01 pixel of the row (one further off
    // cannot cross it; the margin covers rounding, far less) move on as rows
    // do. Each of those is tested exactly.
    const double sy = y + 0.5, across = std::abs(side.y), margin = 0.01;
    auto ends = [&](std::size_t k) {  // a dash's top and bottom, to within rounding
        const double p = a.y + dir.y * starts[k], q = a.y + dir.y * std::min(length, starts[k] + on);
        return std::pair<double, double>{std::min(p, q) - across, std::max(p, q) + across};
    };
    const std::size_t n = starts.size();
    if (dir.y >= 0.0) {  // down the page: k0 and k1 grow
        while (near.k0 < n && ends(near.k0).second <= sy - margin) ++near.k0;
        near.k1 = std::max(near.k1, near.k0);
        while (near.k1 < n && ends(near.k1).first <= sy + margin) ++near.k1;
    } else {  // up the page: k0 and k1 shrink
        while (near.k0 > 0 && ends(near.k0 - 1).first <= sy + margin) --near.k0;
        while (near.k1 > near.k0 && ends(near.k1 - 1).second <= sy - margin) --near.k1;
    }
    glm::dvec2 c[4];
    for (std::size_t k = near.k0; k < near.k1; ++k) {
        quad(k, c);
        PolygonScan::direct_spans(c, 4, y, width, out);
    }
}

Pieces plan_pieces(const Drawing& d, double k, int height) {
    Pieces out;
    auto px = [&](glm::dvec2 p) {
        return glm::dvec2((p.x - d.min.x) * k, (p.y - d.min.y) * k + kPlanTitle * kPlanSuper);
    };
    for (const PlanShape& s : d.shapes) {
        PlanShape mapped = s;
        for (glm::dvec2& p : mapped.points) p = px(p);
        if (s.kind == PlanShape::Kind::Text) {
            add_text(out, mapped, mapped.points.front(), label_pixels(s, k / kPlanSuper) * kPlanSuper, height);
        } else if (s.kind == PlanShape::Kind::Fill) {
            add_polygon(out, mapped.points, s.colour, height);
        } else {
            add_stroke(out, mapped, k, 0.12 * k, 0.08 * k, height);
        }
    }
    // The title and the legend, in the picture's pixels.
    for (PlanShape s : plan_overlay(d, k / kPlanSuper)) {
        for (glm::dvec2& p : s.points) p *= double(kPlanSuper);
        if (s.kind == PlanShape::Kind::Text) {
            add_text(out, s, s.points.front(), s.size * kPlanSuper, height);
        } else if (s.kind == PlanShape::Kind::Fill) {
            add_polygon(out, s.points, s.colour, height);
        } else {
            add_stroke(out, s, kPlanSuper, 5.0 * kPlanSuper, 3.0 * kPlanSuper, height);
        }
    }
    return out;
}

}  // namespace impossible::design
