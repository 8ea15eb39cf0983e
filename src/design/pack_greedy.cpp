// Rooms placed one at a time, for play areas no lattice fits; see
// pack_moves.hpp (place_greedily).
#include <cmath>

#include "design/pack_moves.hpp"

namespace impossible::design {

std::optional<PackState> place_greedily(const PackRules& rules, const std::vector<double>& angles, SplitMix& rng) {
    glm::dvec2 lo = rules.area[0], hi = lo;
    for (const glm::dvec2& p : rules.area) lo = glm::min(lo, p), hi = glm::max(hi, p);
    std::vector<Shape> shapes;
    std::vector<RoomGeom> geoms;
    for (int k = 0; k < rules.rooms; ++k) {
        bool placed = false;
        for (int t = 0; t < kGreedyTries && !placed; ++t) {
            Shape s;
            s.angle = angles[rng.next() % angles.size()];
            const double w = kRoomMinWidth + 0.11 + 0.4 * rng.real(), l = w + 1.5 * rng.real();
            const glm::dvec2 at(lo.x + (hi.x - lo.x) * rng.real(), lo.y + (hi.y - lo.y) * rng.real());
            const double c = std::cos(s.angle), n = std::sin(s.angle);
            const double u = at.x * c + at.y * n, v = -at.x * n + at.y * c;
            const bool long_u = rng.uniform(0, 1) == 1;
            const double hu = (long_u ? l : w) / 2, hv = (long_u ? w : l) / 2;
            s.u0 = u - hu, s.u1 = u + hu, s.v0 = v - hv, s.v1 = v + hv;
            const RoomGeom g = room_geom(s);
            if (!inside_area(g, rules.area)) continue;
            bool ok = true, joined = k == 0;
            for (std::size_t j = 0; j < geoms.size() && ok; ++j) {
                ok = pair_allowed(g, geoms[j], rules.max_overlap);
                joined = joined || (ok && (door_possible(g, geoms[j]) || door_possible(geoms[j], g)));
            }
            if (!ok || !joined) continue;
            shapes.push_back(s), geoms.push_back(g);
            placed = true;
        }
        if (!placed) return std::nullopt;
    }
    return evaluate(rules, shapes);
}

}  // namespace impossible::design
