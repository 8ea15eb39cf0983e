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

#include <cstddef>
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
    int a = -1, b = -1;                  // room indices, a < b
    double area = 0.0;                   // m² shared
    double percent = 0.0;                // of the smaller floor
    double limit = 0.0;                  // overlap_limit_percent of the smaller floor
    bool noticeable = false;             // percent > limit
    std::vector<math::Polygon2> shared;  // the shared floor: one polygon per piece, counter-clockwise
};

// How far the search for overlapping pairs goes. A report lists at most
// `listed` pairs (10,000 identical rooms make 49,995,000), and the search
// stops (leaving a lower bound) after `candidates` pairs whose bounding
// rectangles overlap along x, or after `clipped` pairs that had to be
// clipped (floors that are not axis-aligned rectangles, or rectangle pairs
// within rounding of kMinSharedArea). Axis-aligned rectangles, every floor
// of a layout whose doors do not turn, are counted without clipping, so
// their count is exact up to `candidates`.
inline constexpr std::size_t kMaxListedOverlaps = 1000;
inline constexpr std::size_t kMaxClippedPairs = 1'000'000;
inline constexpr std::size_t kMaxCandidatePairs = 100'000'000;
// The clipped pairs' corners multiplied (n·m a pair: the work of clipping
// or intersecting them, at most 10⁶ for two prisms of 1000 corners) stop
// the search too past this sum; a million box pairs make 1.6·10⁷.
inline constexpr std::size_t kMaxClipWork = 200'000'000;

struct OverlapLimits {
    std::size_t listed = kMaxListedOverlaps;
    std::size_t clipped = kMaxClippedPairs;
    std::size_t candidates = kMaxCandidatePairs;
    std::size_t work = kMaxClipWork;
};

struct Overlaps {
    std::vector<Overlap> listed;  // the first pairs found in order of (a, b), at most `limits.listed`
    std::size_t pairs = 0;        // pairs found that share more than kMinSharedArea, the listed included
    bool exact = true;            // false: the search stopped at a limit, so `pairs` is a lower bound
    bool truncated() const { return !exact || pairs > listed.size(); }
};

// The overlaps of the floors (one simple polygon per room, either winding): every pair that shares more
// than kMinSharedArea, found by a sweep over the floors' bounding rectangles
// sorted by x; memory grows with the floors and `limits.listed`, not with
// the pairs. Without a limit reached, `listed` holds the first pairs in
// order of (a, b).
Overlaps room_overlaps(const std::vector<math::Polygon2>& floors, const OverlapLimits& limits = {});

// One pair's figures (shared may be empty when they do not overlap). Two
// convex floors (every box room's) are clipped as they always were
// (math::clip_to_convex, exact for convex polygons, so box rooms' figures
// stay as they were to the last bit); a pair with a non-convex floor goes
// through intersection() below.
Overlap overlap_of(const math::Polygon2& a, const math::Polygon2& b);

// The intersection of two simple polygons of any shape (either winding,
// convex or not), by Boost.Geometry (design/polygon_clip.cpp; docs/choices.md):
// its pieces, counter-clockwise, without holes (two simple polygons share
// none), and its area in m². Degenerate input (fewer than 3 corners) shares
// nothing. Where the two boundaries meet (cross or touch) at more than
// kMaxLibraryMeetings pairs of edges, or should the library refuse the pair
// (it throws on input it finds invalid), the pieces and the area come from
// the triangles of intersection_area_by_triangles instead: the library's
// time grows with about the square of those points (two combs of 80 teeth
// crossing took 2.5 s, of 160 teeth 46 s; the triangles take 0.4 and 1.5 ms).
inline constexpr std::size_t kMaxLibraryMeetings = 64;
std::vector<math::Polygon2> intersection(const math::Polygon2& a, const math::Polygon2& b);
double intersection_area(const math::Polygon2& a, const math::Polygon2& b);

// The same area without the library: `b` cut into triangles by ear clipping
// and `a` clipped to each (math::clip_to_convex); slower, and the tests'
// second opinion.
double intersection_area_by_triangles(const math::Polygon2& a, const math::Polygon2& b);

// Whether every corner turns the same way (collinear corners allowed).
bool is_convex(const math::Polygon2& poly);

// Whether `inner` lies inside `outer`: at most `tolerance` m² of it outside.
bool polygon_inside(const math::Polygon2& inner, const math::Polygon2& outer, double tolerance);

}  // namespace impossible::design
