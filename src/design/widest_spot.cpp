// The largest circle inside a play area; see widest_spot.hpp.
#include "design/widest_spot.hpp"

#include <algorithm>
#include <cmath>
#include <queue>
#include <vector>

namespace impossible::design {
namespace {

struct SpotCell {
    glm::dvec2 centre{0.0};
    double half = 0.0;      // half its side
    double distance = 0.0;  // from its centre to the boundary, negative outside
    double most() const { return distance + half * std::sqrt(2.0); }
    bool operator<(const SpotCell& other) const { return most() < other.most(); }
};

}  // namespace

WidestSpot widest_spot(const math::Polygon2& area, const AreaIndex& index, double precision) {
    glm::dvec2 lo = area[0], hi = lo;
    for (const glm::dvec2& p : area) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const double side = std::min(hi.x - lo.x, hi.y - lo.y);
    WidestSpot best;
    if (!(side > 0.0)) return best;
    int measured = 0;
    auto measure = [&](glm::dvec2 centre, double half) {
        ++measured;
        const SpotCell cell{centre, half, index.signed_distance(centre)};
        if (cell.distance > best.radius) best.centre = cell.centre, best.radius = cell.distance;
        return cell;
    };
    std::priority_queue<SpotCell> cells;
    for (double x = lo.x; x < hi.x && measured < kMaxSpotCells; x += side)
        for (double z = lo.y; z < hi.y && measured < kMaxSpotCells; z += side)
            cells.push(measure({x + side / 2, z + side / 2}, side / 2));
    measure(0.5 * (lo + hi), 0.0);
    while (measured < kMaxSpotCells) {
        // Nothing in this cell, nor in any left (they are in order), can
        // beat the best by more than the precision.
        if (cells.empty() || cells.top().most() - best.radius <= precision) {
            best.complete = true;
            break;
        }
        const SpotCell cell = cells.top();
        cells.pop();
        const double h = cell.half / 2;
        for (const glm::dvec2 d : {glm::dvec2(-h, -h), glm::dvec2(h, -h), glm::dvec2(-h, h), glm::dvec2(h, h)})
            cells.push(measure(cell.centre + d, h));
    }
    return best;
}

}  // namespace impossible::design
