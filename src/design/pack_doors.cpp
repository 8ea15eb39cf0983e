// Joining packed rooms by doors: a chain where the doors allow one, else a
// tree walked depth first; see pack_search.hpp (join_rooms).
#include <algorithm>
#include <cmath>
#include <functional>

#include "design/pack_search.hpp"
#include "design/splitmix.hpp"

namespace impossible::design {
namespace {

constexpr double kDoorSpacing = 1.2;     // m between the centres of two doors of one room
constexpr int kChainExpansions = 20000;  // steps of the search for a chain
constexpr int kChainsPlaced = 64;        // chains whose doors are tried, at most
constexpr double kDoorStep = 0.1;        // m between the spots tried along a stretch of wall
using Joins = std::vector<std::vector<char>>;

struct Segment {
    glm::dvec2 a{0.0}, b{0.0};
};

double segment_gap(const Segment& s, const Segment& t) {
    if (math::segments_intersect(s.a, s.b, t.a, t.b)) return 0.0;
    return std::min({math::distance_to_segment(s.a, t.a, t.b), math::distance_to_segment(s.b, t.a, t.b),
                     math::distance_to_segment(t.a, s.a, s.b), math::distance_to_segment(t.b, s.a, s.b)});
}

// Chains through every room, found depth first from path[0], the
// neighbour with the fewest onward choices first (Warnsdorff's rule), until
// `accept` takes one or the budget of steps is spent.
bool chain_from(const Joins& adj, std::vector<int>& path, std::vector<char>& used, int& budget,
                const std::function<bool(const std::vector<int>&)>& accept) {
    const int n = static_cast<int>(adj.size());
    if (static_cast<int>(path.size()) == n) return accept(path);
    if (--budget < 0) return false;
    const int last = path.back();
    std::vector<std::pair<int, int>> next;  // onward choices, room
    for (int j = 0; j < n; ++j) {
        if (used[j] || !adj[last][j]) continue;
        int onward = 0;
        for (int k = 0; k < n; ++k) onward += !used[k] && k != j && adj[j][k];
        next.push_back({onward, j});
    }
    std::stable_sort(next.begin(), next.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [onward, j] : next) {
        used[j] = 1, path.push_back(j);
        if (chain_from(adj, path, used, budget, accept)) return true;
        if (budget < 0) return false;
        used[j] = 0, path.pop_back();
    }
    return false;
}

// Rooms depth first from `start`: the order, and (parent, child) per link.
void tree_from(const Joins& adj, int start, std::vector<int>& order, std::vector<std::pair<int, int>>& links) {
    const int n = static_cast<int>(adj.size());
    std::vector<char> seen(n, 0);
    std::vector<std::pair<int, int>> stack{{-1, start}};
    while (!stack.empty()) {
        const auto [parent, room] = stack.back();
        stack.pop_back();
        if (seen[room]) continue;
        seen[room] = 1;
        order.push_back(room);
        if (parent >= 0) links.push_back({parent, room});
        for (int j = n - 1; j >= 0; --j)
            if (!seen[j] && adj[room][j]) stack.push_back({room, j});
    }
}

// Whether a door standing in `room` along `s` is a hole wholly in one of
// its walls or lies wholly off their planes (a door partly in a wall is an
// error in a layout).
bool hole_consistent(const RoomGeom& room, const Segment& s) {
    for (std::size_t i = 0, n = room.outline.size(); i < n; ++i) {
        const glm::dvec2 a = room.outline[i], b = room.outline[(i + 1) % n];
        const double length = glm::distance(a, b);
        const glm::dvec2 d = (b - a) / length, normal(-d.y, d.x);
        if (std::abs(glm::dot(s.a - a, normal)) > 2e-4 || std::abs(glm::dot(s.b - a, normal)) > 2e-4) continue;
        const double t0 = std::min(glm::dot(s.a - a, d), glm::dot(s.b - a, d));
        const double t1 = std::max(glm::dot(s.a - a, d), glm::dot(s.b - a, d));
        const bool within = t0 >= -1e-6 && t1 <= length + 1e-6, off = t1 < -2e-4 || t0 > length + 2e-4;
        if (!within && !off) return false;
    }
    return true;
}

struct Placer {
    const std::vector<RoomGeom>& rooms;
    std::vector<std::vector<Segment>> placed;  // per room, its doors
    std::vector<PackedDoor> doors;
    SplitMix rng;

    bool clear(int room, const Segment& s) const {
        for (const Segment& o : placed[room]) {
            if (glm::distance((o.a + o.b) / 2.0, (s.a + s.b) / 2.0) < kDoorSpacing) return false;
            if (segment_gap(o, s) < kDoorPassage) return false;
        }
        return true;
    }

    bool try_at(int from, int to, int wall, double t) {
        const RoomGeom& f = rooms[from];
        const glm::dvec2 a = f.outline[wall], b = f.outline[(wall + 1) % f.outline.size()];
        const glm::dvec2 d = glm::normalize(b - a);
        const glm::dvec2 c = a + d * t;
        const glm::dvec2 centre(std::round(c.x * 1e6) / 1e6 + 0.0, std::round(c.y * 1e6) / 1e6 + 0.0);
        const Segment s{centre - d * (kPackDoorWidth / 2), centre + d * (kPackDoorWidth / 2)};
        if (!clear(from, s) || !clear(to, s) || !hole_consistent(rooms[to], s)) return false;
        if (!math::contains(rooms[to].outline, s.a, 1e-6) || !math::contains(rooms[to].outline, s.b, 1e-6))
            return false;
        placed[from].push_back(s), placed[to].push_back(s);
        doors.push_back({from, to, centre, {-d.y, d.x}});
        return true;
    }

    // A door between p and c: in either's wall, flush with an end of a
    // stretch first (the widest passage beside it), then its middle.
    bool join(int p, int c) {
        const bool swap = rng.uniform(0, 1) == 1;
        for (int k = 0; k < 2; ++k) {
            const int from = (k == 0) != swap ? p : c, to = from == p ? c : p;
            const int walls = static_cast<int>(rooms[from].outline.size()), first = rng.uniform(0, walls - 1);
            for (int w = 0; w < walls; ++w) {
                const int wall = (first + w) % walls;
                for (const Interval& v : door_stretches(rooms[from], wall, rooms[to])) {
                    for (const double t : {v.lo, v.hi, (v.lo + v.hi) / 2})
                        if (try_at(from, to, wall, t)) return true;
                    for (double t = v.lo + kDoorStep; t < v.hi; t += kDoorStep)
                        if (try_at(from, to, wall, t)) return true;
                }
            }
        }
        return false;
    }
};

// The doors of every link, or nothing when one does not fit.
std::optional<std::vector<PackedDoor>> place_doors(const std::vector<RoomGeom>& rooms,
                                                   const std::vector<std::pair<int, int>>& links, std::uint64_t seed) {
    Placer placer{rooms, std::vector<std::vector<Segment>>(rooms.size()), {}, SplitMix{seed}};
    for (const auto& [p, c] : links)
        if (!placer.join(p, c)) return std::nullopt;
    return std::move(placer.doors);
}

}  // namespace

std::optional<Packing> join_rooms(std::vector<Shape> shapes, std::vector<RoomGeom> rooms, std::uint64_t seed) {
    const int n = static_cast<int>(rooms.size());
    Joins adj(n, std::vector<char>(n, 0));
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
            adj[i][j] = adj[j][i] = door_possible(rooms[i], rooms[j]) || door_possible(rooms[j], rooms[i]);
    SplitMix rng{seed};
    std::vector<int> order;
    std::optional<std::vector<PackedDoor>> doors;
    int budget = kChainExpansions, chains = 0;
    const std::uint64_t door_seed = rng.next();
    auto accept = [&](const std::vector<int>& path) {
        std::vector<std::pair<int, int>> links;
        for (std::size_t k = 0; k + 1 < path.size(); ++k) links.push_back({path[k], path[k + 1]});
        if (++chains > kChainsPlaced) budget = -1;
        doors = place_doors(rooms, links, door_seed);
        if (doors) order = path;
        return doors.has_value();
    };
    const int start = rng.uniform(0, n - 1);
    for (int s = 0; s < n && !doors && budget >= 0; ++s) {
        std::vector<int> path{(start + s) % n};
        std::vector<char> used(n, 0);
        used[path[0]] = 1;
        chain_from(adj, path, used, budget, accept);
    }
    for (int s = 0; s < n && !doors; ++s) {  // no chain whose doors fit: a tree
        std::vector<std::pair<int, int>> links;
        order.clear();
        tree_from(adj, (start + s) % n, order, links);
        if (static_cast<int>(order.size()) != n) return std::nullopt;
        doors = place_doors(rooms, links, door_seed);
    }
    if (!doors) return std::nullopt;
    std::vector<int> position(n);
    for (int k = 0; k < n; ++k) position[order[k]] = k;
    Packing out;
    for (const int r : order) {
        out.shapes.push_back(shapes[r]), out.rooms.push_back(rooms[r]);
        out.floor_area += rooms[r].area;
    }
    for (PackedDoor d : *doors) {
        d.from = position[d.from], d.to = position[d.to];
        out.doors.push_back(d);
    }
    return out;
}

}  // namespace impossible::design
