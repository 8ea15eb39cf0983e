// The widest spot of a play area: the centre of the largest circle inside
// it (its pole of inaccessibility), for `generate`. A room at least 1.5 m
// wide holds a circle 1.5 m across, so a play area whose widest spot is
// narrower holds no room, whatever its size; and where the rooms tried at
// random miss a narrow area's one roomy part (a 10,000-corner star of 500 m
// spikes around a core 4 m across), a room centred on it is tried.
//
// Found as Mapbox's polylabel finds it (Agafonkin 2016): square cells over
// the bounding box, each taken in order of the most its square could hold
// (the distance from its centre to the boundary plus its half-diagonal),
// split in four while that beats the best centre by more than `precision`.
// Each distance is AreaIndex::signed_distance, through the grid of edges.
// Bounded work: at most kMaxSpotCells cells are measured, about 1 µs each;
// past that the best found so far is given, a circle that does lie inside
// (`complete` false). The cells grow with the bounding box's area over the
// spot's: the 10,000-corner star of 500 m spikes around a core 4 m across
// takes 276,550 cells (0.2 s); around a core 1.4 m across, the budget.
#pragma once

#include "design/area_index.hpp"
#include "math/polygon.hpp"

namespace impossible::design {

inline constexpr int kMaxSpotCells = 500'000;

struct WidestSpot {
    glm::dvec2 centre{0.0};
    double radius = 0.0;    // m; 0 when no cell centre lies inside
    bool complete = false;  // the search ended within kMaxSpotCells: no circle is wider by the precision
};

// `index` is of `area`.
WidestSpot widest_spot(const math::Polygon2& area, const AreaIndex& index, double precision = 0.01);

}  // namespace impossible::design
