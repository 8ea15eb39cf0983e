// How much rooms overlap on the physical floor, and whether people are
// likely to notice.
//
// The overlap of two rooms is the area their floors share (on the physical
// floor, design/placement.hpp) as a percentage of the smaller room's floor.
// Suma et al. (2012, "Impossible Spaces: Maximizing Natural Walking in
// Virtual Environments with Self-Overlapping Architecture", IEEE TVCG 18(4))
// found that overlaps of up to about 56 % went unnoticed between small
// rooms and up to about 31 % between larger ones. The rule here: a pair
// whose smaller room has at most kSmallRoomArea m² of floor may overlap by
// kSmallRoomLimit %, any other pair by kLargeRoomLimit %; above that the
// overlap is flagged as noticeable. The 16 m² cut-off (a 4 × 4 m room) is
// this project's choice, not the paper's (docs/designer.md).
#pragma once

#include <vector>

#include "math/polygon.hpp"

namespace impossible::design {

inline constexpr double kSmallRoomArea = 16.0;   // m²
inline constexpr double kSmallRoomLimit = 56.0;  // %
inline constexpr double kLargeRoomLimit = 31.0;  // %
inline constexpr double kMinSharedArea = 1e-6;   // m²; less is touching, not sharing

// The published threshold for a pair whose smaller floor is `smaller_area` m².
double overlap_limit_percent(double smaller_area);

struct Overlap {
    int a = -1, b = -1;       // room indices, a < b
    double area = 0.0;        // m² shared
    double percent = 0.0;     // of the smaller floor
    double limit = 0.0;       // overlap_limit_percent of the smaller floor
    bool noticeable = false;  // percent > limit
    math::Polygon2 shared;    // the shared floor
};

// The overlaps of convex floors (one per room), every pair that shares more
// than kMinSharedArea, in order of (a, b).
std::vector<Overlap> room_overlaps(const std::vector<math::Polygon2>& floors);

// One pair's figures (shared may be empty when they do not overlap).
Overlap overlap_of(const math::Polygon2& a, const math::Polygon2& b);

}  // namespace impossible::design
