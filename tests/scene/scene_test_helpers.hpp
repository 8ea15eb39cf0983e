// Small builders and geometric checks shared by the scene mesh tests.
#pragma once

#include <array>
#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "common/layouts.hpp"
#include "layout/layout.hpp"
#include "scene/scene.hpp"

namespace impossible::scene::test {

using impossible::test::make_room;

using impossible::test::make_portal;

// The portal as the loader marks a hole in a face of its room.
inline layout::Portal in_face(layout::Portal p, layout::Face face) {
    p.hole_face = static_cast<int>(face);
    return p;
}

// A box prop from `min` to `max`.
inline layout::BoxProp box_prop(glm::dvec3 min, glm::dvec3 max) {
    layout::BoxProp b;
    b.min = min;
    b.max = max;
    return b;
}

// The standard test room: 4 × 3 × 4, floor at y = 0, centred on the y axis.
inline layout::Layout one_room_layout() {
    layout::Layout l;
    l.source = "<test>";
    l.rooms.push_back(make_room("room", {-2.0, 0.0, -2.0}, {2.0, 3.0, 2.0}));
    l.start.room = 0;
    return l;
}

struct Triangle {
    std::array<const Vertex*, 3> v;

    glm::dvec3 p(int k) const { return glm::dvec3(v[static_cast<std::size_t>(k)]->position); }
    glm::dvec3 cross() const { return glm::cross(p(1) - p(0), p(2) - p(0)); }
    double area() const { return 0.5 * glm::length(cross()); }
    glm::dvec3 geometric_normal() const { return glm::normalize(cross()); }
    glm::dvec3 centroid() const { return (p(0) + p(1) + p(2)) / 3.0; }
};

inline std::vector<Triangle> triangles(const Scene& s, IndexRange r) {
    std::vector<Triangle> out;
    const std::size_t end = std::size_t{r.first} + r.count;
    for (std::size_t k = r.first; k + 3 <= end && k + 3 <= s.indices.size(); k += 3) {
        out.push_back({{&s.vertices[s.indices[k]], &s.vertices[s.indices[k + 1]], &s.vertices[s.indices[k + 2]]}});
    }
    return out;
}

inline double total_area(const std::vector<Triangle>& ts) {
    double a = 0.0;
    for (const Triangle& t : ts) a += t.area();
    return a;
}

// Whether the point lies on the triangle (in its plane, inside or on an edge).
inline bool covers(const Triangle& t, const glm::dvec3& q) {
    const glm::dvec3 n = t.cross();
    if (std::abs(glm::dot(glm::normalize(n), q - t.p(0))) > 1e-6) return false;
    for (int k = 0; k < 3; ++k) {
        const glm::dvec3 e = t.p((k + 1) % 3) - t.p(k);
        if (glm::dot(glm::cross(e, q - t.p(k)), n) < 0.0) return false;
    }
    return true;
}

using Point = std::tuple<float, float, float>;
inline Point key(const glm::vec3& p) { return {p.x, p.y, p.z}; }

// Directed edges (bitwise positions) and how often each occurs.
inline std::map<std::pair<Point, Point>, int> directed_edges(const std::vector<Triangle>& ts) {
    std::map<std::pair<Point, Point>, int> edges;
    for (const Triangle& t : ts) {
        for (std::size_t k = 0; k < 3; ++k) {
            ++edges[{key(t.v[k]->position), key(t.v[(k + 1) % 3]->position)}];
        }
    }
    return edges;
}

// A closed, consistently wound surface without T-junctions: every directed
// edge occurs exactly once and its reverse exactly once.
inline bool closed_and_consistent(const std::vector<Triangle>& ts) {
    const auto edges = directed_edges(ts);
    for (const auto& [e, count] : edges) {
        if (count != 1) return false;
        const auto reverse = edges.find({e.second, e.first});
        if (reverse == edges.end() || reverse->second != 1) return false;
    }
    return !edges.empty();
}

// A closed surface regardless of winding: every undirected edge twice.
inline bool closed_undirected(const std::vector<Triangle>& ts) {
    std::map<std::pair<Point, Point>, int> edges;
    for (const Triangle& t : ts) {
        for (std::size_t k = 0; k < 3; ++k) {
            Point a = key(t.v[k]->position), b = key(t.v[(k + 1) % 3]->position);
            if (b < a) std::swap(a, b);
            ++edges[{a, b}];
        }
    }
    for (const auto& [e, count] : edges) {
        if (count != 2) return false;
    }
    return !edges.empty();
}

inline std::vector<Triangle> concat(std::vector<Triangle> a, const std::vector<Triangle>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

}  // namespace impossible::scene::test
