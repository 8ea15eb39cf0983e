// Internal to src/render: a chart of the light cache (light_cache.cpp):
// one plane of a room's triangles and its cells in the atlas.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "render/lights/light_cache.hpp"

namespace impossible::render {

// One plane of a room's triangles, in its room's coordinates less the cell
// origin: p = u · a + v · b + normal · offset for plane coordinates (a, b).
struct CacheChart {
    int room = -1;
    glm::dvec3 normal{0.0}, u{0.0}, v{0.0};
    double offset = 0.0;
    glm::dvec2 lo{0.0}, hi{0.0};  // the triangles' extent in plane coordinates
    double side = 0.0;            // a cell's side
    glm::ivec2 cells{0};          // the chart's cells, one of margin on every side
    glm::ivec2 at{0};             // its first cell in the atlas
    std::vector<std::array<std::uint32_t, 3>> triangles;

    glm::dvec2 plane_point(const glm::dvec3& p) const { return {glm::dot(p, u), glm::dot(p, v)}; }
    glm::dvec3 point_at(const glm::dvec2& q) const { return u * q.x + v * q.y + normal * offset; }
    // Corner (i, j) of the chart's cells: cell 0 starts a cell before lo.
    glm::dvec3 grid_point(int i, int j) const { return point_at(lo + side * (glm::dvec2(i, j) - 1.0)); }
    glm::dvec2 atlas_point(const glm::dvec3& p) const { return (plane_point(p) - lo) / side + 1.0 + glm::dvec2(at); }
};

}  // namespace impossible::render
