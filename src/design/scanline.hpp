// Even-odd scanline filling of polygons, one pixel row at a time from the
// top (the plan's rasteriser, plan_raster.cpp).
//
// A pixel (x, y) is inside a polygon when its centre (x + 0.5, y + 0.5) is,
// by the even-odd rule: on row y the polygon's edges that cross the line
// through the centres are found (edge i, from corner i to corner i - 1,
// crosses where exactly one end lies below it), their crossings sorted, and
// each pair of crossings covers the pixels whose centres lie between them.
// A polygon of many corners keeps an edge table sorted by its edges' tops
// and a list of the edges that the current row may cross, so a row costs
// the edges it crosses, not all the edges.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "math/polygon.hpp"

namespace impossible::design {

struct Span {
    int x0 = 0, x1 = 0;  // the pixels x0..x1 (inclusive)
};

// The rows a polygon may cover in an image `height` rows high: first..last,
// empty (first > last) when none.
struct RowRange {
    int first = 0, last = -1;
};
RowRange polygon_rows(const glm::dvec2* points, std::size_t count, int height);

// One polygon's scan, for rows visited in increasing order.
class PolygonScan {
public:
    // The corners stay owned by the caller and must outlive the scan.
    PolygonScan(const glm::dvec2* points, std::size_t count);

    // Appends the spans of row y (clipped to 0..width-1) to `out`, left to
    // right; `xs` is scratch space. Rows must come in increasing order.
    void spans(int y, int width, std::vector<double>& xs, std::vector<Span>& out);

    // Up to this many corners, every edge is tested on every row: such a
    // scan keeps no state, and direct_spans does the same without one.
    static constexpr std::size_t kDirectEdges = 16;
    static void direct_spans(const glm::dvec2* points, std::size_t count, int y, int width, std::vector<Span>& out);

private:
    const glm::dvec2* points_;
    std::size_t count_;
    std::vector<std::uint32_t> by_top_;  // edges in order of their upper end (many corners only)
    std::size_t next_ = 0;               // the next edge of by_top_ to join `active_`
    std::vector<std::uint32_t> active_;  // edges that may cross this row or a later one
};

}  // namespace impossible::design
