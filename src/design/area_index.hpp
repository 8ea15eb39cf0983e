// Whether an axis-aligned box lies inside a play area, for `generate`,
// which asks that of up to a million candidate rooms.
//
// A play area of up to kPlainCorners corners is asked as everywhere else:
// math::convex_inside, the box's area outside at most 1e-9 m², found by
// clipping the play area to the box (every corner, every time). Beyond
// that, a star of 10,000 corners took 10 s per 1,000 corners when no room
// fit, so the box is tested against an index instead: a grid over the play
// area whose cells list the edges that pass through them, and whether each
// cell without an edge lies inside. The box is inside when no edge meets
// the box shrunk by kEdgeClearance on every side, and its centre is inside;
// the two tests disagree only where the play area pokes into the box by
// less than kEdgeClearance.
#pragma once

#include <cstdint>
#include <vector>

#include "math/polygon.hpp"

namespace impossible::design {

class AreaIndex {
public:
    static constexpr std::size_t kPlainCorners = 64;
    static constexpr double kEdgeClearance = 1e-9;  // m

    // `area` must be a simple polygon; it is copied.
    explicit AreaIndex(math::Polygon2 area, bool force_index = false);

    bool box_inside(const glm::dvec2& lo, const glm::dvec2& hi) const;

    // The edges box_inside has tested against a box so far, through the
    // grid: the work its callers bound (generate_boxes.cpp, kMaxBoxWork).
    std::uint64_t edges_tested() const { return edges_tested_; }

    // The distance from `p` to the play area's boundary, positive inside and
    // negative outside (for design/widest_spot.hpp). Through the grid, the
    // edges of the cells in rings around p's until no edge farther out can
    // be nearer; the side from the nearest edge, or at a corner from both of
    // its edges.
    double signed_distance(const glm::dvec2& p) const;

private:
    enum : std::uint8_t { kOutside, kInside, kCrossed };
    math::Polygon2 area_;
    double turn_ = 1.0;  // 1 for corners anticlockwise, -1 clockwise
    bool indexed_ = false;
    glm::dvec2 origin_{0.0};
    double cell_ = 1.0;
    int nx_ = 0, nz_ = 0;
    std::vector<std::uint8_t> state_;   // per cell
    std::vector<std::uint32_t> start_;  // per cell + 1: where its edges begin in edges_
    std::vector<std::uint32_t> edges_;  // edge i runs from corner i to corner i + 1
    mutable std::uint64_t edges_tested_ = 0;

    void build();
    bool indexed_box_inside(const glm::dvec2& lo, const glm::dvec2& hi) const;
    // The edge nearest to p (and its parameter there, 0..1).
    void nearest_edge(const glm::dvec2& p, std::uint32_t& edge, double& t) const;
};

}  // namespace impossible::design
