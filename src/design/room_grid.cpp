// The occupancy grid and A* of one room; see room_grid.hpp.
#include "design/room_grid.hpp"

#include <algorithm>
#include <cmath>
#include <queue>

#include "design/placement.hpp"
#include "layout/room_shape.hpp"

namespace impossible::design {
namespace {

// The x range of segment ab within the strip z0 <= z <= z1, or false.
bool strip_span(const glm::dvec2& a, const glm::dvec2& b, double z0, double z1, double& lo, double& hi) {
    double t0 = 0.0, t1 = 1.0;
    const double dz = b.y - a.y;
    if (dz == 0.0) {
        if (a.y < z0 || a.y > z1) return false;
    } else {
        const double u = (z0 - a.y) / dz, v = (z1 - a.y) / dz;
        t0 = std::max(t0, std::min(u, v));
        t1 = std::min(t1, std::max(u, v));
        if (t0 > t1) return false;
    }
    const double x0 = a.x + t0 * (b.x - a.x), x1 = a.x + t1 * (b.x - a.x);
    lo = std::min(x0, x1), hi = std::max(x0, x1);
    return true;
}

// The cells of a prism room's grid whose centres lie inside its floor
// polygon and at least `radius` from every wall: the cells between the
// polygon's crossings of each row of centres (even-odd), less those that
// some wall's `radius` band reaches (tested exactly, distance_to_segment,
// in the rows and columns the band can reach). The same cells as testing
// every centre against every wall, in about rows × walls + the bands'
// cells instead of rows × columns × walls steps.
std::vector<unsigned char> prism_cells(const math::Polygon2& poly, glm::dvec2 origin, double cell, int nx, int nz,
                                       double radius) {
    std::vector<unsigned char> ok(static_cast<std::size_t>(nx) * nz, 0);
    const std::size_t n = poly.size();
    std::vector<double> xs;
    for (int k = 0; k < nz; ++k) {
        const double z = origin.y + (k + 0.5) * cell;
        xs.clear();
        for (std::size_t e = 0; e < n; ++e) {
            const glm::dvec2 a = poly[e], b = poly[(e + 1) % n];
            if ((a.y <= z) != (b.y <= z)) xs.push_back(a.x + (z - a.y) / (b.y - a.y) * (b.x - a.x));
        }
        std::sort(xs.begin(), xs.end());
        for (std::size_t j = 0; j + 1 < xs.size(); j += 2) {
            const int i0 = std::max(0, static_cast<int>(std::ceil((xs[j] - origin.x) / cell - 0.5)));
            const int i1 = std::min(nx - 1, static_cast<int>(std::floor((xs[j + 1] - origin.x) / cell - 0.5)));
            for (int i = i0; i <= i1; ++i) ok[static_cast<std::size_t>(k) * nx + i] = 1;
        }
    }
    for (std::size_t e = 0; e < n; ++e) {
        const glm::dvec2 a = poly[e], b = poly[(e + 1) % n];
        const int k0 = std::max(0, static_cast<int>(std::floor((std::min(a.y, b.y) - radius - origin.y) / cell)));
        const int k1 = std::min(nz - 1, static_cast<int>(std::ceil((std::max(a.y, b.y) + radius - origin.y) / cell)));
        for (int k = k0; k <= k1; ++k) {
            const double z = origin.y + (k + 0.5) * cell;
            double lo = 0.0, hi = 0.0;
            if (!strip_span(a, b, z - radius, z + radius, lo, hi)) continue;
            const int i0 = std::max(0, static_cast<int>(std::floor((lo - radius - origin.x) / cell)) - 1);
            const int i1 = std::min(nx - 1, static_cast<int>(std::ceil((hi + radius - origin.x) / cell)) + 1);
            for (int i = i0; i <= i1; ++i) {
                unsigned char& c = ok[static_cast<std::size_t>(k) * nx + i];
                const glm::dvec2 centre = origin + glm::dvec2(i + 0.5, k + 0.5) * cell;
                if (c && math::distance_to_segment(centre, a, b) < radius) c = 0;
            }
        }
    }
    return ok;
}

}  // namespace

RoomGrid::RoomGrid(const layout::Layout& layout, int room_index, const math::dmat4& to_physical,
                   const math::Polygon2& play_area, const GridOptions& o, const std::vector<Obstacle>* obstacles) {
    const std::vector<Obstacle> props = obstacles ? *obstacles : listed_obstacles(layout, room_index, o.head_height);
    const layout::Room& room = layout.rooms[room_index];
    origin_ = {room.min.x, room.min.z};
    const glm::dvec2 extent{room.max.x - room.min.x, room.max.z - room.min.z};
    cell_ = std::max(o.cell, std::max(extent.x, extent.y) / kMaxCells);
    nx_ = std::max(1, static_cast<int>(std::ceil(extent.x / cell_)));
    nz_ = std::max(1, static_cast<int>(std::ceil(extent.y / cell_)));
    // A prism room's floor polygon inset by the body radius; a box room
    // keeps its rectangle test.
    const bool prism = layout::is_prism(room);
    const std::vector<unsigned char> inset =
        prism ? prism_cells(layout::floor_outline(room), origin_, cell_, nx_, nz_, o.body_radius)
              : std::vector<unsigned char>{};
    std::vector<std::array<glm::dvec2, 2>> doors;
    for (const layout::Portal& p : layout.portals)
        if (p.room == room_index && p.kind == layout::PortalKind::Door) doors.push_back(door_line(p, math::dmat4(1.0)));
    free_.assign(static_cast<std::size_t>(nx_) * nz_, 0);
    for (int k = 0; k < nz_; ++k) {
        for (int i = 0; i < nx_; ++i) {
            const glm::dvec2 c = centre(i, k);
            bool ok = prism ? inset[index(i, k)] != 0
                            : c.x >= room.min.x + o.body_radius && c.x <= room.max.x - o.body_radius &&
                                  c.y >= room.min.z + o.body_radius && c.y <= room.max.z - o.body_radius;
            for (std::size_t n = 0; ok && n < props.size(); ++n) ok = obstacle_distance(c, props[n]) >= o.body_radius;
            for (std::size_t n = 0; ok && n < doors.size(); ++n)
                ok = math::distance_to_segment(c, doors[n][0], doors[n][1]) >= o.body_radius;
            if (ok && !play_area.empty()) {
                const glm::dvec2 p = to_floor(to_physical, {c.x, 0.0, c.y});
                ok = math::contains(play_area, p, 0.0) && math::distance_to_boundary(play_area, p) >= o.edge_margin;
            }
            free_[index(i, k)] = ok ? 1 : 0;
        }
    }
}

bool RoomGrid::cell_of(const glm::dvec2& p, int& i, int& k) const {
    const glm::dvec2 f = (p - origin_) / cell_;
    if (!(f.x >= 0.0 && f.y >= 0.0)) return false;
    i = static_cast<int>(f.x);
    k = static_cast<int>(f.y);
    return i < nx_ && k < nz_;
}

bool RoomGrid::free(const glm::dvec2& p) const {
    int i = 0, k = 0;
    return cell_of(p, i, k) && free_[index(i, k)] != 0;
}

std::optional<glm::dvec2> RoomGrid::nearest_free(const glm::dvec2& p) const {
    if (free(p)) return p;
    std::optional<glm::dvec2> best;
    double best_d = INFINITY;
    for (int k = 0; k < nz_; ++k)
        for (int i = 0; i < nx_; ++i) {
            if (!free_[index(i, k)]) continue;
            const double d = glm::distance(centre(i, k), p);
            if (d < best_d) best_d = d, best = centre(i, k);
        }
    return best;
}

bool RoomGrid::clear(const glm::dvec2& a, const glm::dvec2& b) const {
    const int steps = std::max(1, static_cast<int>(std::ceil(glm::distance(a, b) / (0.25 * cell_))));
    for (int s = 0; s <= steps; ++s)
        if (!free(a + (b - a) * (double(s) / steps))) return false;
    return true;
}

std::vector<glm::dvec2> RoomGrid::straighten(const std::vector<glm::dvec2>& path) const {
    std::vector<glm::dvec2> out{path.front()};
    std::size_t at = 0;
    while (at + 1 < path.size()) {
        std::size_t next = path.size() - 1;
        while (next > at + 1 && !clear(path[at], path[next])) --next;
        out.push_back(path[next]);
        at = next;
    }
    return out;
}

std::optional<std::vector<glm::dvec2>> RoomGrid::find_path(const glm::dvec2& from, const glm::dvec2& to) const {
    int si = 0, sk = 0, gi = 0, gk = 0;
    if (!free(from) || !free(to) || !cell_of(from, si, sk) || !cell_of(to, gi, gk)) return std::nullopt;
    if (clear(from, to)) return std::vector<glm::dvec2>{from, to};
    const int goal = index(gi, gk);
    std::vector<double> cost(free_.size(), INFINITY);
    std::vector<int> came(free_.size(), -1);
    using Entry = std::pair<double, int>;  // (cost + heuristic, cell)
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
    cost[index(si, sk)] = 0.0;
    open.push({0.0, index(si, sk)});
    while (!open.empty()) {
        const int at = open.top().second;
        open.pop();
        if (at == goal) break;
        const int i = at % nx_, k = at / nx_;
        for (int dk = -1; dk <= 1; ++dk)
            for (int di = -1; di <= 1; ++di) {
                const int ni = i + di, nk = k + dk;
                if ((di == 0 && dk == 0) || ni < 0 || nk < 0 || ni >= nx_ || nk >= nz_) continue;
                const int n = index(ni, nk);
                if (!free_[n] || (di != 0 && dk != 0 && (!free_[index(ni, k)] || !free_[index(i, nk)]))) continue;
                const double c = cost[at] + (di != 0 && dk != 0 ? std::sqrt(2.0) : 1.0) * cell_;
                if (c >= cost[n]) continue;
                cost[n] = c;
                came[n] = at;
                open.push({c + glm::distance(centre(ni, nk), to), n});
            }
    }
    if (came[goal] < 0 && goal != index(si, sk)) return std::nullopt;
    std::vector<glm::dvec2> path{to};
    for (int at = came[goal]; at >= 0 && at != index(si, sk); at = came[at]) path.push_back(centre(at % nx_, at / nx_));
    path.push_back(from);
    std::reverse(path.begin(), path.end());
    return straighten(path);
}

}  // namespace impossible::design
