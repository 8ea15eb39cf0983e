// Triangulation of an axis-aligned rectangular face minus convex quadrilateral
// holes of any orientation: the fallback for a face holding a portal whose
// rectangle is not axis-aligned in it (room_mesh.cpp handles the usual case).
//
// The face is cut into vertical slabs at every hole corner's a-coordinate (and
// at the given extra cuts). No hole corner lies inside a slab, so within it
// each hole is bounded by two straight edges that cross the whole slab, and the
// face minus holes is a stack of trapezoids between them. Exact in area; the
// slab cuts leave T-junctions on hole edges.
#pragma once

#include <array>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "scene/mesh_writer.hpp"

namespace impossible::scene {

struct SlabFace {
    int axis = 0;        // the face's normal axis
    double plane = 0.0;  // its coordinate on that axis
    PlaneAxes in;        // e_a × e_b = normal
    glm::dvec2 lo{0.0};  // (a, b) range of the face
    glm::dvec2 hi{0.0};
    glm::dvec3 normal{0.0};
    glm::dvec3 color{0.0};
    double checker = 0.0;
    std::vector<double> cuts;                      // extra a-coordinates to cut at (layout's)
    std::vector<std::array<glm::dvec2, 4>> holes;  // (a, b) corners, in order around each
};

void append_face_slabs(MeshWriter& out, const SlabFace& face);

}  // namespace impossible::scene
