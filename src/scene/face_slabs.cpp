#include "scene/face_slabs.hpp"

#include <algorithm>
#include <cstdint>
#include <map>
#include <utility>

namespace impossible::scene {

namespace {

// b on the line through p and q at a = x, exact at both ends.
double b_at(const glm::dvec2& p, const glm::dvec2& q, double x) {
    if (x == p.x) return p.y;
    if (x == q.x) return q.y;
    return p.y + (q.y - p.y) * ((x - p.x) / (q.x - p.x));
}

// A hole's extent across one slab: its lower and upper edge at both ends.
struct Span {
    double lower0, lower1, upper0, upper1, middle;
};

// The hole's span over [x0, x1], if the hole covers the slab's middle.
bool hole_span(const std::array<glm::dvec2, 4>& hole, double x0, double x1, Span& span) {
    const double xm = 0.5 * (x0 + x1);
    int found = 0;
    double b0[2], b1[2], bm[2];
    for (std::size_t e = 0; e < 4 && found < 2; ++e) {
        const glm::dvec2& p = hole[e];
        const glm::dvec2& q = hole[(e + 1) % 4];
        if (std::min(p.x, q.x) < xm && std::max(p.x, q.x) > xm) {
            b0[found] = b_at(p, q, x0);
            b1[found] = b_at(p, q, x1);
            bm[found] = b_at(p, q, xm);
            ++found;
        }
    }
    if (found != 2) return false;
    const int lo = bm[0] <= bm[1] ? 0 : 1;
    span = {b0[lo], b1[lo], b0[1 - lo], b1[1 - lo], bm[lo]};
    return true;
}

}  // namespace

void append_face_slabs(MeshWriter& out, const SlabFace& face) {
    std::vector<double> all = {face.lo.x, face.hi.x};
    for (const double x : face.cuts) all.push_back(std::clamp(x, face.lo.x, face.hi.x));
    for (const auto& hole : face.holes) {
        for (const glm::dvec2& c : hole) all.push_back(std::clamp(c.x, face.lo.x, face.hi.x));
    }
    std::sort(all.begin(), all.end());
    // One cut per float value (no slab thinner than the vertices can show),
    // keeping the face's own bounds exact.
    std::vector<double> xs;
    for (const double x : all) {
        if (!xs.empty() && out.local(x, face.in.a) == out.local(xs.back(), face.in.a)) {
            if (x == face.hi.x) xs.back() = x;
            continue;
        }
        xs.push_back(x);
    }

    std::map<std::pair<double, double>, std::uint32_t> ids;  // shared vertices by (a, b)
    const float plane = out.local(face.plane, face.axis);
    const auto id = [&](double a, double b) {
        const auto [it, added] = ids.try_emplace({a, b}, 0u);
        if (added) {
            const glm::vec3 p =
                plane_point(face.axis, plane, face.in, out.local(a, face.in.a), out.local(b, face.in.b));
            it->second = out.vertex(p, face.normal, face.color, face.checker);
        }
        return it->second;
    };
    // Counter-clockwise in (a, b), so facing the normal; drops empty triangles.
    const auto triangle = [&](glm::dvec2 p, glm::dvec2 q, glm::dvec2 r) {
        const double twice_area = (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
        if (twice_area > 0.0) out.triangle(id(p.x, p.y), id(q.x, q.y), id(r.x, r.y));
    };

    for (std::size_t s = 0; s + 1 < xs.size(); ++s) {
        const double x0 = xs[s], x1 = xs[s + 1];
        std::vector<Span> spans;
        for (const auto& hole : face.holes) {
            Span span;
            if (hole_span(hole, x0, x1, span)) spans.push_back(span);
        }
        std::sort(spans.begin(), spans.end(), [](const Span& l, const Span& r) { return l.middle < r.middle; });
        // The trapezoids between the face's bottom, the holes and its top.
        double floor0 = face.lo.y, floor1 = face.lo.y;
        const auto region = [&](double top0, double top1) {
            top0 = std::clamp(top0, face.lo.y, face.hi.y);
            top1 = std::clamp(top1, face.lo.y, face.hi.y);
            triangle({x0, floor0}, {x1, floor1}, {x1, top1});
            triangle({x0, floor0}, {x1, top1}, {x0, top0});
        };
        for (const Span& span : spans) {
            region(span.lower0, span.lower1);
            floor0 = std::clamp(span.upper0, face.lo.y, face.hi.y);
            floor1 = std::clamp(span.upper1, face.lo.y, face.hi.y);
        }
        region(face.hi.y, face.hi.y);
    }
}

}  // namespace impossible::scene
