// The front of a portal that is a rectangular hole in a face cut into a grid
// (room_mesh.cpp for box rooms, prism_mesh.cpp for the walls of prism rooms):
// the grid points the hole spans, so that the front shares the face's
// vertices along the hole's edges (no T-junction).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/vec2.hpp>

#include "scene/portal_box.hpp"

namespace impossible::scene {

// The front of a hole covering the grid cells [i0, i1) × [j0, j1) of a face
// whose in-plane axes (a, b) satisfy e_a × e_b = the face's normal. `corners`
// are the portal's front corners (math::box_corners' order) in (a, b);
// point(i, j) is grid point (i, j). Columns run along the portal's right and
// rows along its up.
template <class PointAt>
FrontGrid grid_front(const std::array<glm::dvec2, 4>& corners, PointAt point, std::size_t i0, std::size_t i1,
                     std::size_t j0, std::size_t j1) {
    // The portal's right and up along the face's axes, from its corners.
    const glm::dvec2 along_r = corners[1] - corners[0];
    const glm::dvec2 along_u = corners[3] - corners[0];
    const bool r_on_a = std::abs(along_r.x) >= std::abs(along_r.y);
    const bool r_up = (r_on_a ? along_r.x : along_r.y) > 0.0;  // r along +axis
    const bool u_up = (r_on_a ? along_u.y : along_u.x) > 0.0;
    const std::size_t r_lo = r_on_a ? i0 : j0, r_hi = r_on_a ? i1 : j1;
    const std::size_t u_lo = r_on_a ? j0 : i0, u_hi = r_on_a ? j1 : i1;
    FrontGrid g;
    g.cols = static_cast<int>(r_hi - r_lo + 1);
    g.rows = static_cast<int>(u_hi - u_lo + 1);
    for (int j = 0; j < g.rows; ++j) {
        for (int i = 0; i < g.cols; ++i) {
            const std::size_t ri = r_up ? r_lo + static_cast<std::size_t>(i) : r_hi - static_cast<std::size_t>(i);
            const std::size_t uj = u_up ? u_lo + static_cast<std::size_t>(j) : u_hi - static_cast<std::size_t>(j);
            g.points.push_back(r_on_a ? point(ri, uj) : point(uj, ri));
        }
    }
    return g;
}

// Emits the open cells of an na × nb grid of points (open[j·(na-1)+i] for
// cell (i, j)), two triangles each, making each point's vertex the first time
// a cell uses it (`make_vertex(i, j)`), in the same order for every face that
// is cut into a grid.
template <class Out, class Open, class MakeVertex>
void emit_open_cells(Out& out, std::size_t na, std::size_t nb, const Open& open, MakeVertex make_vertex) {
    constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> ids(na * nb, kNone);  // made when first used
    const auto id = [&](std::size_t i, std::size_t j) {
        std::uint32_t& v = ids[j * na + i];
        if (v == kNone) v = make_vertex(i, j);
        return v;
    };
    for (std::size_t j = 0; j + 1 < nb; ++j) {
        for (std::size_t i = 0; i + 1 < na; ++i) {
            if (!open[j * (na - 1) + i]) continue;
            out.triangle(id(i, j), id(i + 1, j), id(i + 1, j + 1));
            out.triangle(id(i, j), id(i + 1, j + 1), id(i, j + 1));
        }
    }
}

}  // namespace impossible::scene
