// The packer's rules and its local search; see pack_moves.hpp.
#include "design/pack_moves.hpp"

#include <algorithm>
#include <cmath>

namespace impossible::design {
namespace {

constexpr double kMovesPi = 3.14159265358979323846;
constexpr double kNarrowest = kRoomMinWidth + 0.01;  // m: rounding to millimetres keeps 1.5 m
constexpr double kShortestArm = 0.3;                 // m: no wall of an L shorter than this

using Adjacency = std::vector<std::vector<char>>;

bool joinable(const RoomGeom& a, const RoomGeom& b) { return door_possible(a, b) || door_possible(b, a); }

bool connected(const Adjacency& adj) {
    const std::size_t n = adj.size();
    std::vector<char> seen(n, 0);
    std::vector<std::size_t> stack{0};
    seen[0] = 1;
    std::size_t count = 1;
    while (!stack.empty()) {
        const std::size_t i = stack.back();
        stack.pop_back();
        for (std::size_t j = 0; j < n; ++j)
            if (adj[i][j] && !seen[j]) seen[j] = 1, ++count, stack.push_back(j);
    }
    return count == n;
}

// A corridor in a corner of the play area's bounding rectangle, as wide as
// the room it would replace, its arcs about that corner.
Shape corner_corridor(const Shape& old, glm::dvec2 lo, glm::dvec2 hi, SplitMix& rng) {
    const int corner = rng.uniform(0, 3);
    Shape s;
    s.kind = Shape::Kind::Arc;
    s.centre = {corner == 1 || corner == 2 ? hi.x : lo.x, corner >= 2 ? hi.y : lo.y};
    s.a0 = corner * kMovesPi / 2, s.a1 = s.a0 + kMovesPi / 2;
    const double w = std::max(shape_width(old), kNarrowest + 0.05),
                 reach = std::min({hi.x - lo.x, hi.y - lo.y, kMaxRoomSpan - 0.1});
    s.r1 = w + rng.real() * std::max(0.0, reach - w);
    s.r0 = s.r1 - w;
    return s;
}

Shape turned(const Shape& s, double by) {
    const double uc = (s.u0 + s.u1) / 2, vc = (s.v0 + s.v1) / 2, c = std::cos(s.angle), n = std::sin(s.angle);
    const glm::dvec2 centre(uc * c - vc * n, uc * n + vc * c);
    Shape t = s;
    t.angle = s.angle + by;
    const double c2 = std::cos(t.angle), n2 = std::sin(t.angle);
    const double du = centre.x * c2 + centre.y * n2 - uc, dv = -centre.x * n2 + centre.y * c2 - vc;
    t.u0 += du, t.u1 += du, t.v0 += dv, t.v1 += dv;
    return t;
}

Shape arm_move(const Shape& s, double step, int move, SplitMix& rng) {
    Shape t = s;
    if (s.kind == Shape::Kind::Rect) {
        t.kind = Shape::Kind::L;
        t.arm_side = rng.uniform(0, 3), t.arm_high = rng.uniform(0, 1) == 1;
        const double side = t.arm_side < 2 ? s.u1 - s.u0 : s.v1 - s.v0;
        t.arm_width = kNarrowest + rng.real() * (side - 0.3 - kNarrowest);
        t.arm_length = kShortestArm + step;
        if (side - 0.3 < kNarrowest) t.arm_length = -1.0;  // refused below
        return t;
    }
    const double side = s.arm_side < 2 ? s.u1 - s.u0 : s.v1 - s.v0;
    if (move == 0) t.arm_length += step;
    if (move == 1) t.arm_width = std::min(side - 0.3, t.arm_width + (rng.uniform(0, 1) ? step : -step));
    return t;
}

// One random change to one room (it may break rules; the caller checks).
Shape propose(const Shape& s, glm::dvec2 lo, glm::dvec2 hi, SplitMix& rng) {
    static const double kSteps[] = {0.05, 0.1, 0.2, 0.4};
    const double step = kSteps[rng.uniform(0, 3)], sign = rng.uniform(0, 1) ? 1.0 : -1.0;
    const int move = rng.uniform(0, 11);
    Shape t = s;
    if (s.kind == Shape::Kind::Arc) {
        switch (move % 6) {
            case 0: t.r0 -= step; break;
            case 1: t.r1 += step; break;
            case 2: t.a0 -= step / t.r1; break;
            case 3: t.a1 += step / t.r1; break;
            case 4: t.centre.x += sign * step; break;
            default: t.centre.y += sign * step; break;
        }
        return t;
    }
    switch (move) {
        case 0: t.u0 -= step; break;
        case 1: t.u1 += step; break;
        case 2: t.v0 -= step; break;
        case 3: t.v1 += step; break;
        case 4: t.u0 += sign * step, t.u1 += sign * step; break;
        case 5: t.v0 += sign * step, t.v1 += sign * step; break;
        case 6:
        case 7:
        case 8: t = arm_move(s, step, move - 6, rng); break;
        case 9: t = turned(s, sign * step * kMovesPi / 36); break;  // 0.25 to 2 degrees
        case 10: t = corner_corridor(s, lo, hi, rng); break;
        default: break;
    }
    return t;
}

bool shape_sane(const Shape& s) {
    if (s.kind == Shape::Kind::Arc) return s.r0 > 0.5 && s.r1 > s.r0 && s.a1 > s.a0 && s.a1 - s.a0 <= 1.5 * kMovesPi;
    if (s.kind == Shape::Kind::L) {
        const double side = s.arm_side < 2 ? s.u1 - s.u0 : s.v1 - s.v0;
        return s.arm_length >= kShortestArm - 1e-9 && s.arm_width >= kNarrowest && s.arm_width <= side - 0.3 + 1e-9;
    }
    return true;
}

}  // namespace

std::optional<PackState> evaluate(const PackRules& rules, const std::vector<Shape>& shapes) {
    PackState s;
    s.shapes = shapes;
    for (const Shape& shape : shapes) {
        if (shape_width(shape) < kNarrowest - 1e-9) return std::nullopt;
        s.geoms.push_back(room_geom(shape));
        if (!inside_area(s.geoms.back(), rules.area)) return std::nullopt;
        s.area += s.geoms.back().area;
    }
    const std::size_t n = shapes.size();
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j)
            if (!pair_allowed(s.geoms[i], s.geoms[j], rules.max_overlap)) return std::nullopt;
    // Joined: a union of the rooms reached so far, grown by any door.
    std::vector<char> in(n, 0);
    in[0] = 1;
    for (bool grew = true; grew;) {
        grew = false;
        for (std::size_t j = 0; j < n; ++j)
            for (std::size_t i = 0; i < n && !in[j]; ++i)
                if (in[i] && joinable(s.geoms[i], s.geoms[j])) in[j] = 1, grew = true;
    }
    if (std::find(in.begin(), in.end(), 0) != in.end()) return std::nullopt;
    return s;
}

void improve(const PackRules& rules, PackState& state, SplitMix& rng, int moves_per_room) {
    const int n = static_cast<int>(state.shapes.size());
    glm::dvec2 lo = rules.area[0], hi = lo;
    for (const glm::dvec2& p : rules.area) lo = glm::min(lo, p), hi = glm::max(hi, p);
    Adjacency adj(n, std::vector<char>(n, 0));
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) adj[i][j] = adj[j][i] = joinable(state.geoms[i], state.geoms[j]);
    for (int move = 0; move < moves_per_room * n; ++move) {
        const int r = rng.uniform(0, n - 1);
        const Shape t = propose(state.shapes[r], lo, hi, rng);
        if (!shape_sane(t) || shape_width(t) < kNarrowest) continue;
        const RoomGeom g = room_geom(t);
        if (g.area < state.geoms[r].area - 1e-4 || std::max(g.hi.x - g.lo.x, g.hi.y - g.lo.y) > kMaxRoomSpan) continue;
        if (!inside_area(g, rules.area)) continue;
        bool ok = true;
        for (int j = 0; j < n && ok; ++j) ok = j == r || pair_allowed(g, state.geoms[j], rules.max_overlap);
        if (!ok) continue;
        Adjacency next = adj;
        for (int j = 0; j < n; ++j)
            if (j != r) next[r][j] = next[j][r] = joinable(g, state.geoms[j]);
        if (n > 1 && !connected(next)) continue;
        adj = std::move(next);
        state.area += g.area - state.geoms[r].area;
        state.shapes[r] = t, state.geoms[r] = g;
    }
}

}  // namespace impossible::design
