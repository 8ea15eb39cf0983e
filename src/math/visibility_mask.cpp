// Visibility masks in tangent space (see visibility_mask.hpp).
#include "math/visibility_mask.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

namespace impossible::math {

namespace {

double triangle_turn(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

std::string point_text(const glm::dvec2& p) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "(%.9g, %.9g)", p.x, p.y);
    return buf;
}

// The mesh with equal coordinates merged: each triangle's three vertex
// numbers, counter-clockwise (y up), and where the triangles' edges are.
struct Merged {
    std::vector<glm::dvec2> points;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> edges;  // directed, ccw: its triangle
    double area = 0.0;                                                     // the triangles' areas summed
};

std::optional<OutlineProblem> merge(const std::vector<glm::dvec2>& vertices, const std::vector<std::uint32_t>& indices,
                                    Merged& m) {
    std::map<std::pair<double, double>, std::uint32_t> number_of;
    std::vector<std::uint32_t> number(vertices.size());
    for (std::size_t k = 0; k < vertices.size(); ++k) {
        const auto [it, added] =
            number_of.emplace(std::pair{vertices[k].x, vertices[k].y}, static_cast<std::uint32_t>(m.points.size()));
        if (added) m.points.push_back(vertices[k]);
        number[k] = it->second;
    }
    for (std::size_t t = 0; 3 * t + 2 < indices.size(); ++t) {
        std::uint32_t c[3];
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t i = indices[3 * t + static_cast<std::size_t>(k)];
            if (i >= vertices.size())
                return OutlineProblem{
                    t, "index " + std::to_string(i) + " is past the " + std::to_string(vertices.size()) + " vertices"};
            c[k] = number[i];
        }
        const double o = triangle_turn(m.points[c[0]], m.points[c[1]], m.points[c[2]]);
        if (o == 0.0) return OutlineProblem{t, "the triangle is degenerate (its corners are collinear or repeat)"};
        if (o < 0.0) std::swap(c[1], c[2]);
        m.area += 0.5 * std::abs(o);
        for (int k = 0; k < 3; ++k) {
            const auto [it, added] = m.edges.emplace(std::pair{c[k], c[(k + 1) % 3]}, t);
            if (!added)
                return OutlineProblem{t, "the triangle overlaps triangle " + std::to_string(it->second) +
                                             " (both lie on the same side of their shared edge)"};
        }
    }
    return std::nullopt;
}

}  // namespace

glm::dvec2 tangent_to_image(const FovTangents& t, const glm::dvec2& p) {
    return {(p.x - t.left) / (t.right - t.left), (t.up - p.y) / (t.up - t.down)};
}

Polygon2 clip_to_image(const Polygon2& visible) {
    const bool inside = std::all_of(visible.begin(), visible.end(), [](const glm::dvec2& p) {
        return p.x >= 0.0 && p.x <= 1.0 && p.y >= 0.0 && p.y <= 1.0;
    });
    if (inside) return visible;
    Polygon2 out;
    for (glm::dvec2 p : clip_to_convex(visible, rectangle({0.0, 0.0}, {1.0, 1.0}))) {
        p = glm::clamp(p, glm::dvec2(0.0), glm::dvec2(1.0));  // the meeting points' rounding
        if (out.empty() || out.back() != p) out.push_back(p);
    }
    while (out.size() > 1 && out.front() == out.back()) out.pop_back();
    return out;
}

MeshOutline triangles_outline(const std::vector<glm::dvec2>& vertices, const std::vector<std::uint32_t>& indices) {
    if (indices.size() < 3 || indices.size() % 3 != 0)
        return {{},
                OutlineProblem{
                    0, "the indices must be whole triangles, three each (got " + std::to_string(indices.size()) + ")"}};
    Merged m;
    if (std::optional<OutlineProblem> problem = merge(vertices, indices, m)) return {{}, problem};
    // The outline: the edges no other triangle has the other way round,
    // each vertex left by at most one of them.
    std::map<std::uint32_t, std::uint32_t> next;
    std::size_t start_triangle = indices.size();
    std::uint32_t start = 0;
    for (const auto& [edge, t] : m.edges) {
        if (m.edges.count({edge.second, edge.first})) continue;
        if (!next.emplace(edge.first, edge.second).second)
            return {
                {},
                OutlineProblem{t, "the triangles' outline passes twice through " + point_text(m.points[edge.first]) +
                                      ": their union is not one simple polygon"}};
        if (t < start_triangle) {
            start_triangle = t;
            start = edge.first;
        }
    }
    Polygon2 outline;
    std::uint32_t at = start;
    do {
        outline.push_back(m.points[at]);
        const auto it = next.find(at);
        if (it == next.end() || outline.size() > next.size()) break;
        at = it->second;
    } while (at != start);
    if (outline.size() != next.size())
        return {{},
                OutlineProblem{0, "the triangles' outline is " + std::to_string(next.size()) +
                                      " edges in more than one loop: their union must be one simple polygon "
                                      "(one piece, no holes, triangles meeting edge to edge)"}};
    if (std::optional<PolygonProblem> problem = simple_polygon_problem(outline))
        return {{}, OutlineProblem{0, "the triangles' outline is not a simple polygon: " + problem->message}};
    if (!(std::abs(area(outline) - m.area) <= 1e-9 * m.area))
        return {{}, OutlineProblem{0, "the triangles overlap (their areas add up to more than their union's)"}};
    return {outline, std::nullopt};
}

}  // namespace impossible::math
