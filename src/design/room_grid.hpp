// Where a walker may stand inside one room, and the shortest way between two
// points there: an occupancy grid over the room's floor (in the room's own
// coordinates) searched with A* (Hart, Nilsson and Raphael 1968), the path
// then straightened by skipping corners that have a clear line of sight.
//
// A cell is free when its centre is at least `body_radius` from the room's
// walls (inside the floor polygon of a prism room, so a path goes round the
// inner corner of an L and along a bent corridor), from every prop that reaches below the head (box props, and glTF
// props by the bounding box of their triangles; moving props where design/obstacles.hpp puts them), and from the floor line of
// every door of the room (so a path never walks through a door it does not
// mean to; mirrors and windows lie in the room's faces and are passed like
// walls), and, with a play area, when the centre maps inside it, at least
// `edge_margin` from its edge. Units metres; floor points are (x, z).
#pragma once

#include <optional>
#include <vector>

#include "design/obstacles.hpp"
#include "layout/layout.hpp"
#include "math/conventions.hpp"
#include "math/polygon.hpp"

namespace impossible::design {

struct GridOptions {
    double cell = 0.05;         // m; grown for large rooms so a side has at most kMaxCells cells
    double body_radius = 0.25;  // m from walls, props and doors
    double edge_margin = 0.1;   // m from the play area's edge
    double head_height = 1.6;   // props wholly above this + 0.2 m are not obstacles
};

inline constexpr int kMaxCells = 400;

class RoomGrid {
public:
    // `to_physical` places the room on the floor; `play_area` may be empty;
    // `props` are the room's obstacles (design/obstacles.hpp); without them,
    // its props where they are listed.
    RoomGrid(const layout::Layout& layout, int room, const math::dmat4& to_physical, const math::Polygon2& play_area,
             const GridOptions& options, const std::vector<Obstacle>* props = nullptr);

    bool free(const glm::dvec2& p) const;  // the cell holding p is free
    // The free point nearest p (p itself if free), or nothing in a room with no free cell.
    std::optional<glm::dvec2> nearest_free(const glm::dvec2& p) const;
    // A clear way from `from` to `to` (both included), or nothing.
    std::optional<std::vector<glm::dvec2>> find_path(const glm::dvec2& from, const glm::dvec2& to) const;
    // Whether every point of the segment is in free cells.
    bool clear(const glm::dvec2& a, const glm::dvec2& b) const;

private:
    int nx_ = 0, nz_ = 0;
    double cell_ = 0.05;
    glm::dvec2 origin_{0.0};
    std::vector<unsigned char> free_;

    int index(int i, int k) const { return k * nx_ + i; }
    bool cell_of(const glm::dvec2& p, int& i, int& k) const;
    glm::dvec2 centre(int i, int k) const { return origin_ + glm::dvec2(i + 0.5, k + 0.5) * cell_; }
    std::vector<glm::dvec2> straighten(const std::vector<glm::dvec2>& path) const;
};

}  // namespace impossible::design
