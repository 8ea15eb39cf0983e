// Internal to src/scene: how a prism room's faces are cut (prism_mesh.cpp
// writes them): each wall in its frame with its holes, its cuts along the
// wall and the heights of the vertices on its sides, and the holes of floor
// and ceiling.
//
// Heights: a wall holding upright holes is a grid (as box rooms' faces),
// cut at the top and bottom edges of its holes and of the holes in the
// walls next to it that are grids too (a run of such walls shares its
// heights, so that neighbouring grids meet vertex to vertex); every other
// wall is triangulated by the tessellator with, on each side, the heights
// of the grid beside it there (or only floor and ceiling). So a hole cuts
// only its own run of walls, not the whole room.
#pragma once

#include <array>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "layout/layout.hpp"
#include "layout/room_shape.hpp"

namespace impossible::scene {

// A portal that is a hole in a face, in the face's (s, t).
struct PrismHole {
    int portal = -1;
    std::array<glm::dvec2, 4> corners;  // math::box_corners' front corners
    glm::dvec2 lo{0.0}, hi{0.0};        // their bounding rectangle
    bool aligned = true;
};

// Wall i in its frame: s = 0 at corner i (a), s = length at corner i + 1 (b).
struct PrismWall {
    layout::FaceFrame frame;
    glm::dvec2 a{0.0}, b{0.0};  // (x, z)
    double length = 0.0;        // negative where s runs from b towards a
    // Its cuts along s, ascending: its ends, its holes' edges (a grid wall),
    // and where floor and ceiling holes meet it.
    std::vector<double> s_lines;
    std::vector<PrismHole> holes;
    bool grid = false;         // holes, all upright in it: cut into a grid (s_lines × rows)
    std::vector<double> rows;  // a grid's heights, ascending (its run's)
    // The heights of the vertices on its sides at the smallest and the
    // largest s, ascending from the floor to the ceiling.
    std::vector<double> low_side, high_side;

    // The point (s, y) of the wall, in layout coordinates; the wall's ends
    // are its corners exactly.
    glm::dvec3 point(double s, double y) const {
        const glm::dvec2 xz = s == 0.0 ? a : s == length ? b : a + (s / length) * (b - a);
        return {xz.x, y, xz.y};
    }
    // s_lines from corner a to corner b.
    std::vector<double> from_a() const;
};

struct PrismPlan {
    std::vector<PrismWall> walls;
    std::array<layout::FaceFrame, 2> caps;            // floor, ceiling
    std::array<std::vector<PrismHole>, 2> cap_holes;  // in the caps' (s, t)
};

// The plan of layout.rooms[room] (a prism), with the holes of its portals
// among room_portals.
PrismPlan plan_prism(const layout::Layout& layout, int room, const std::vector<int>& room_portals);

}  // namespace impossible::scene
