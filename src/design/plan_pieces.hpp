// The plan's shapes as polygons to fill, in canvas pixels (the plan
// rasterised 3 × 3 times larger; plan_raster.cpp): a fill is its polygon, a
// stroke a quad per segment plus round joins, a dashed segment one run of
// dashes. A run keeps only where each dash starts along the segment, and
// makes a dash's quad when a row needs it: the outlines of 10,000 stacked
// unreachable rooms of 20 m a side are 4 million dashes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "design/plan.hpp"
#include "design/scanline.hpp"

namespace impossible::design {

inline constexpr int kPlanSuper = 3;        // canvas pixels per image pixel, each way
inline constexpr double kPlanTitle = 28.0;  // image pixels above the floor for the title (plan_size)

// The dashes of one dashed segment from `a` along `dir`.
struct DashRun {
    glm::dvec2 a{0.0}, dir{0.0}, side{0.0};  // side: half the stroke's width, across it
    double length = 0.0, on = 0.0;           // the segment's length, a dash's
    std::vector<double> starts;              // where each dash starts, as the stroke adds up its period

    // The dashes near the rows being drawn, [k0, k1): rows must come in
    // increasing order, each with the same cursor, which starts as start().
    struct Cursor {
        std::size_t k0 = 0, k1 = 0;
    };
    Cursor start() const;
    // Appends the spans of row y of every dash it crosses, dash by dash.
    void spans(int y, int width, Cursor& near, std::vector<Span>& out) const;
    // Dash k's corners.
    void quad(std::size_t k, glm::dvec2* corners) const;
};

// One polygon (or run of dashes) to fill, its colour and its rows.
struct Piece {
    std::size_t first = 0, count = 0;  // its corners in Pieces::points; a run: its index in Pieces::runs, count 0
    float r = 0, g = 0, b = 0, a = 0;
    RowRange rows;
    bool run = false;
};

struct Pieces {
    std::vector<glm::dvec2> points;
    std::vector<DashRun> runs;
    std::vector<Piece> list;  // in drawing order
};

// Every shape but text, `k` canvas pixels a metre, on a canvas `height` rows high.
Pieces plan_pieces(const Drawing& d, double k, int height);

}  // namespace impossible::design
