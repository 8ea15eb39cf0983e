#include "scene/prism_plan.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "math/portal.hpp"

namespace impossible::scene {

std::vector<double> PrismWall::from_a() const {
    std::vector<double> s = s_lines;
    if (length < 0.0) std::reverse(s.begin(), s.end());
    return s;
}

namespace {

// As room_mesh.cpp's: a rectangle whose corners lie within this of their
// bounding rectangle's in a wall's (s, t) is upright in it.
constexpr double kPrismAlignTolerance = 1e-6;

// The hole of `rect` in the face `frame`; a wall's clamps its corners to the
// wall's rectangle [bounds[0], bounds[1]] (a floor's or ceiling's is left as
// it is: the tessellator cuts it to the polygon).
PrismHole prism_hole(const layout::FaceFrame& frame, int portal, const math::PortalRect& rect,
                     const glm::dvec2* bounds) {
    math::dvec3 c[8];
    math::box_corners(rect, c);
    PrismHole h;
    h.portal = portal;
    h.lo = glm::dvec2(std::numeric_limits<double>::infinity());
    h.hi = -h.lo;
    for (std::size_t k = 0; k < 4; ++k) {
        glm::dvec2 st = layout::to_face(frame, c[k]);
        if (bounds != nullptr) st = glm::clamp(st, bounds[0], bounds[1]);
        h.corners[k] = st;
        h.lo = glm::min(h.lo, st);
        h.hi = glm::max(h.hi, st);
    }
    const auto near = [](double x, double a, double b) {
        return std::abs(x - a) <= kPrismAlignTolerance || std::abs(x - b) <= kPrismAlignTolerance;
    };
    for (const glm::dvec2& p : h.corners) {
        h.aligned = h.aligned && near(p.x, h.lo.x, h.hi.x) && near(p.y, h.lo.y, h.hi.y);
    }
    return h;
}

void sort_unique(std::vector<double>& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
}

void add_prism_hole(PrismPlan& plan, const layout::Room& room, int p, const layout::Portal& portal) {
    const auto face = static_cast<std::size_t>(portal.hole_face);
    if (face < 2) {
        plan.cap_holes[face].push_back(prism_hole(plan.caps[face], p, portal.rect, nullptr));
        return;
    }
    PrismWall& w = plan.walls[face - 2];
    const glm::dvec2 bounds[2] = {{std::min(0.0, w.length), room.min.y}, {std::max(0.0, w.length), room.max.y}};
    const PrismHole h = prism_hole(w.frame, p, portal.rect, bounds);
    w.grid = w.grid && h.aligned;  // (set true before the first hole)
    w.holes.push_back(h);
}

// Floor and ceiling holes' corners within this of a wall (the loader's
// "inside" tolerance) lie on it: a trapdoor flush with a wall.
constexpr double kPrismSnap = 1e-4;

// A floor or ceiling hole's corners that lie on a wall (within kPrismSnap)
// are moved onto it, to the wall's point there, which becomes a cut of the
// wall (s_lines): the hole, the floor's outline, the wall and the trapdoor's
// front then meet vertex to vertex, as box rooms' faces do.
void snap_to_walls(PrismPlan& plan, const layout::FaceFrame& cap, double y, PrismHole& h) {
    for (glm::dvec2& st : h.corners) {
        const glm::dvec3 p = layout::from_face(cap, st);
        for (PrismWall& w : plan.walls) {
            const double s = glm::dot(glm::dvec3(p.x - w.a.x, 0.0, p.z - w.a.y), w.frame.s_axis);
            const double d = glm::dot(glm::dvec3(p.x - w.a.x, 0.0, p.z - w.a.y), w.frame.normal);
            if (std::abs(d) > kPrismSnap || s < std::min(0.0, w.length) - kPrismSnap ||
                s > std::max(0.0, w.length) + kPrismSnap)
                continue;
            const double at = std::abs(s) <= kPrismSnap ? 0.0 : std::abs(s - w.length) <= kPrismSnap ? w.length : s;
            w.s_lines.push_back(at);
            st = layout::to_face(cap, w.point(at, y));
            break;
        }
    }
}

// The runs of grid walls (consecutive, round the polygon) share their
// heights; each wall's sides take the heights of the grid beside them.
void plan_heights(PrismPlan& plan, double y0, double y1) {
    const std::size_t n = plan.walls.size();
    std::vector<double> floor_ceiling = {y0, y1};
    // Start after a wall that is not a grid, so that no run wraps round
    // (all grids: one run).
    std::size_t start = 0;
    while (start < n && plan.walls[start].grid) ++start;
    std::vector<std::size_t> run;
    const auto close_run = [&] {
        std::vector<double> heights = floor_ceiling;
        for (const std::size_t i : run)
            for (const PrismHole& h : plan.walls[i].holes) heights.insert(heights.end(), {h.lo.y, h.hi.y});
        sort_unique(heights);
        for (const std::size_t i : run) plan.walls[i].rows = heights;
        run.clear();
    };
    for (std::size_t k = 1; k <= n; ++k) {
        const std::size_t i = (start + k) % n;
        if (plan.walls[i].grid)
            run.push_back(i);
        else if (!run.empty())
            close_run();
    }
    if (!run.empty()) close_run();
    // Corner i joins wall i - 1 (its b) and wall i (its a).
    const auto corner = [&](std::size_t i) -> const std::vector<double>& {
        const PrismWall& here = plan.walls[i % n];
        const PrismWall& before = plan.walls[(i + n - 1) % n];
        return here.grid ? here.rows : before.grid ? before.rows : floor_ceiling;
    };
    for (std::size_t i = 0; i < n; ++i) {
        PrismWall& w = plan.walls[i];
        w.low_side = corner(w.length > 0.0 ? i : i + 1);
        w.high_side = corner(w.length > 0.0 ? i + 1 : i);
    }
}

}  // namespace

PrismPlan plan_prism(const layout::Layout& layout, int room_index, const std::vector<int>& room_portals) {
    const layout::Room& room = layout.rooms[static_cast<std::size_t>(room_index)];
    PrismPlan plan;
    for (int i = 0; i < layout::wall_count(room); ++i) {
        const layout::Wall lw = layout::wall(room, i);
        PrismWall w;
        w.grid = true;
        w.frame = layout::face_frame(room, 2 + i);
        w.a = lw.a;
        w.b = lw.b;
        w.length = glm::dot(glm::dvec3(lw.b.x - lw.a.x, 0.0, lw.b.y - lw.a.y), w.frame.s_axis);
        plan.walls.push_back(w);
    }
    for (std::size_t f = 0; f < 2; ++f) plan.caps[f] = layout::face_frame(room, static_cast<int>(f));
    for (const int p : room_portals) {
        const layout::Portal& portal = layout.portals[static_cast<std::size_t>(p)];
        if (portal.room != room_index || portal.hole_face < 0) continue;
        assert(portal.hole_face < layout::face_count(room));
        add_prism_hole(plan, room, p, portal);
    }
    for (std::size_t f = 0; f < 2; ++f)
        for (PrismHole& h : plan.cap_holes[f]) snap_to_walls(plan, plan.caps[f], f == 0 ? room.min.y : room.max.y, h);
    for (PrismWall& w : plan.walls) {
        w.s_lines.insert(w.s_lines.end(), {std::min(0.0, w.length), std::max(0.0, w.length)});
        w.grid = w.grid && !w.holes.empty();
        if (w.grid)
            for (const PrismHole& h : w.holes) w.s_lines.insert(w.s_lines.end(), {h.lo.x, h.hi.x});
        sort_unique(w.s_lines);
    }
    plan_heights(plan, room.min.y, room.max.y);
    return plan;
}

}  // namespace impossible::scene
