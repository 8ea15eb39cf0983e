// Lattices of strips on the play area, improved by a local search; see
// pack_search.hpp.
#include "design/pack_search.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "design/overlap.hpp"
#include "design/pack_moves.hpp"
#include "design/splitmix.hpp"
#include "math/conventions.hpp"

namespace impossible::design {
namespace {

constexpr double kInset = 0.001;           // m: rooms keep this far inside the play area before rounding
constexpr double kMaxSpan = kMaxRoomSpan;  // m of a larger floor that one lattice covers
constexpr double kWidthStep = 0.05;        // m between the widths tried
constexpr double kNearBest = 0.98;         // the seed picks among lattices at least this good
constexpr double kPairBudget = 4e6;        // pairs of rooms tested by the lattice scan, at most
constexpr int kJoinTries = 12;             // lattices tried when doors cannot join one
constexpr int kGreedyRestarts = 24;        // tries at placing rooms one at a time

// The play area in a frame turned by `angle`: corner (x, z) becomes (U, V),
// or (V, U) when swapped.
math::Polygon2 in_frame(const math::Polygon2& area, double angle, bool swapped) {
    const double c = std::cos(angle), s = std::sin(angle);
    math::Polygon2 out;
    for (const glm::dvec2& p : area) {
        const glm::dvec2 uv(p.x * c + p.y * s, -p.x * s + p.y * c);
        out.push_back(swapped ? glm::dvec2(uv.y, uv.x) : uv);
    }
    return out;
}

// The longest stretch along the first coordinate, within [wlo, whi], over
// which the band b0 <= second <= b1 lies inside `poly` (frame coordinates).
std::optional<Interval> band_span(const math::Polygon2& poly, double b0, double b1, double wlo, double whi) {
    std::vector<Interval> blocked;
    for (std::size_t i = 0, n = poly.size(); i < n; ++i) {
        const glm::dvec2 p = poly[i], q = poly[(i + 1) % n];
        if (std::max(p.y, q.y) <= b0 + 1e-9 || std::min(p.y, q.y) >= b1 - 1e-9) continue;
        double t0 = 0.0, t1 = 1.0;
        if (p.y != q.y) {
            const double ta = (b0 - p.y) / (q.y - p.y), tb = (b1 - p.y) / (q.y - p.y);
            t0 = std::clamp(std::min(ta, tb), 0.0, 1.0), t1 = std::clamp(std::max(ta, tb), 0.0, 1.0);
        }
        const double ua = p.x + (q.x - p.x) * t0, ub = p.x + (q.x - p.x) * t1;
        blocked.push_back({std::min(ua, ub), std::max(ua, ub)});
    }
    std::sort(blocked.begin(), blocked.end(), [](const Interval& a, const Interval& b) { return a.lo < b.lo; });
    std::optional<Interval> best;
    double from = wlo;
    auto consider = [&](double lo, double hi) {
        if (hi - lo <= 2 * kInset) return;
        if (!math::contains(poly, {(lo + hi) / 2, (b0 + b1) / 2}, 0.0)) return;
        if (!best || hi - lo > best->hi - best->lo) best = Interval{lo + kInset, hi - kInset};
    };
    for (const Interval& b : blocked) {
        if (b.lo > from) consider(from, std::min(b.lo, whi));
        from = std::max(from, b.hi);
    }
    if (from < whi) consider(from, whi);
    return best;
}

// The frame directions the lattices are tried in: the play area's two
// longest edge directions (modulo a quarter turn) and a seeded angle.
std::vector<double> frame_angles(const math::Polygon2& area, SplitMix& rng) {
    std::vector<std::pair<double, double>> weight;  // angle, summed edge length
    for (std::size_t i = 0, n = area.size(); i < n; ++i) {
        const glm::dvec2 d = area[(i + 1) % n] - area[i];
        double a = std::fmod(std::atan2(d.y, d.x), math::kPi / 2);
        if (a < 0.0) a += math::kPi / 2;
        if (a >= math::kPi / 2 - 1e-12) a = 0.0;
        auto it =
            std::find_if(weight.begin(), weight.end(), [&](const auto& w) { return std::abs(w.first - a) < 1e-9; });
        if (it == weight.end()) weight.push_back({a, 0.0}), it = weight.end() - 1;
        it->second += glm::length(d);
    }
    std::stable_sort(weight.begin(), weight.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
    std::vector<double> angles;
    for (std::size_t i = 0; i < weight.size() && angles.size() < 2; ++i) angles.push_back(weight[i].first);
    angles.push_back(rng.real() * math::kPi / 2);
    return angles;
}

struct Frame {
    double angle = 0.0;
    math::Polygon2 uv, vu;  // the play area in (U, V) and in (V, U)
    Interval u, v;          // the window the lattice covers
};

struct Lattice {
    int frame = 0, n1 = 0;
    double w1 = 0.0, w2 = 0.0;
    double spread = 1.0;  // the share of the window's width the bands spread over
    int m1 = 1, m2 = 1;   // rooms per band (a band cut along its length)
    double reach = 1.0;   // a cut band's rooms are this many times the band over m long
};

// The band cuts tried: rooms per band, and how far a cut band's rooms
// overlap (1: they only touch).
constexpr int kCuts[] = {1, 2, 3, 4, 6};
constexpr double kReaches[] = {1.0, 1.4};
constexpr int kMaxCutRooms = 24;  // more rooms: no cut bands (the scan would take too long)

// Spreads tried: the whole window, and its middle for floors that narrow
// towards their ends (a hexagon, a triangle).
constexpr double kSpreads[] = {1.0, 0.75, 0.5};

// Cuts the span into m rooms, each `reach` times span / m long (at least
// kRoomMinWidth), spread evenly along it.
std::vector<Interval> cuts(const Interval& span, int m, double reach) {
    if (m == 1) return {span};
    const double length = std::max(kRoomMinWidth + 0.01, (span.hi - span.lo) / m * reach);
    if (length > span.hi - span.lo) return {};
    std::vector<Interval> out;
    for (int i = 0; i < m; ++i) {
        const double lo = span.lo + (span.hi - span.lo - length) * i / (m - 1);
        out.push_back({lo, i + 1 == m ? span.hi : lo + length});
    }
    return out;
}

// n strips of width w spread evenly over the middle `spread` of the window,
// each cut into m rooms.
bool strips(const Frame& f, bool along_u, int n, double w, const Lattice& l, std::vector<Shape>& out) {
    const double spread = l.spread;
    const int m = along_u ? l.m1 : l.m2;
    const Interval window = along_u ? f.v : f.u, along = along_u ? f.u : f.v;
    const double middle = (window.lo + window.hi) / 2, half = (window.hi - window.lo) * spread / 2;
    const Interval across{std::max(window.lo, middle - std::max(half, w / 2)),
                          std::min(window.hi, middle + std::max(half, w / 2))};
    if (n == 0) return true;
    if (across.hi - across.lo < w) return false;
    for (int i = 0; i < n; ++i) {
        const double b0 =
            n == 1 ? (across.lo + across.hi - w) / 2 : across.lo + (across.hi - across.lo - w) * i / (n - 1);
        const std::optional<Interval> span = band_span(along_u ? f.uv : f.vu, b0, b0 + w, along.lo, along.hi);
        if (!span || span->hi - span->lo < kRoomMinWidth + 0.01) return false;
        const std::vector<Interval> pieces = cuts(*span, m, l.reach);
        if (pieces.empty()) return false;
        for (const Interval& piece : pieces) {
            Shape s;
            s.angle = f.angle;
            if (along_u) {
                s.u0 = piece.lo, s.u1 = piece.hi, s.v0 = b0, s.v1 = b0 + w;
            } else {
                s.u0 = b0, s.u1 = b0 + w, s.v0 = piece.lo, s.v1 = piece.hi;
            }
            out.push_back(s);
        }
    }
    return true;
}

struct Context {
    const PackRules& rules;
    std::vector<Frame> frames;
};

std::optional<PackState> lattice_layout(const Context& c, const Lattice& l) {
    std::vector<Shape> shapes;
    const Frame& f = c.frames[l.frame];
    const int n2 = (c.rules.rooms - l.n1 * l.m1) / l.m2;
    if (!strips(f, true, l.n1, l.w1, l, shapes) || !strips(f, false, n2, l.w2, l, shapes)) return {};
    return evaluate(c.rules, shapes);
}

Frame make_frame(const math::Polygon2& area, double angle, SplitMix& rng) {
    Frame f;
    f.angle = angle;
    f.uv = in_frame(area, angle, false), f.vu = in_frame(area, angle, true);
    glm::dvec2 lo = f.uv[0], hi = lo;
    for (const glm::dvec2& p : f.uv) lo = glm::min(lo, p), hi = glm::max(hi, p);
    auto window = [&](double a, double b) {
        const double start = b - a > kMaxSpan ? a + rng.real() * (b - a - kMaxSpan) : a;
        return Interval{start + kInset, std::min(b, start + kMaxSpan) - kInset};
    };
    f.u = window(lo.x, hi.x), f.v = window(lo.y, hi.y);
    return f;
}

// The widths tried: steps from the narrowest, and the widths at which k
// bands fill the window exactly (rooms that only touch).
std::vector<double> widths(const Interval& across, double step, int bands) {
    std::vector<double> out;
    const double widest = std::min(across.hi - across.lo, kMaxSpan);
    for (double w = kRoomMinWidth + 0.01; w <= widest + 1e-9; w += step) out.push_back(w);
    for (int k = std::max(1, bands); k >= 1; --k)
        if ((across.hi - across.lo) / k >= kRoomMinWidth + 0.01 && (across.hi - across.lo) / k <= widest + 1e-9)
            out.push_back((across.hi - across.lo) / k);
    return out;
}

struct Scored {
    Lattice lattice;
    double area = 0.0;
};

// One split of the rooms between the axes: equal widths first, then each
// axis's own width near the best.
void scan_split(const Context& c, Lattice base, double step, std::vector<Scored>& found) {
    const Frame& f = c.frames[base.frame];
    std::optional<Scored> best;
    for (const double w : widths(base.n1 > 0 ? f.v : f.u, step, std::max(base.n1, 1))) {
        Lattice l = base;
        l.w1 = l.w2 = w;
        if (const auto e = lattice_layout(c, l); e && (!best || e->area > best->area)) best = Scored{l, e->area};
    }
    if (!best) return;
    found.push_back(*best);
    if (base.m1 > 1 || base.m2 > 1) return;  // cut bands: the widths' scan only
    for (int a = -3; a <= 3; ++a)
        for (int b = -3; b <= 3; ++b) {
            Lattice l = best->lattice;
            l.w1 += a * step, l.w2 += b * step;
            if ((a == 0 && b == 0) || l.w1 < kRoomMinWidth + 0.01 - 1e-9 || l.w2 < kRoomMinWidth + 0.01 - 1e-9)
                continue;
            if (const auto e = lattice_layout(c, l)) found.push_back({l, e->area});
        }
}

// Every split of the rooms between the two axes, in every frame and spread.
std::vector<Scored> scan(const Context& c) {
    const int n = c.rules.rooms;
    const double pairs = std::max(1.0, n * (n - 1) / 2.0);
    std::vector<int> splits;
    for (int n1 = 0; n1 <= n; ++n1)
        if (n <= 16 || std::abs(2 * n1 - n) <= 8 || n1 == 0 || n1 == n) splits.push_back(n1);
    const double tries = static_cast<double>(c.frames.size() * splits.size() * std::size(kSpreads)) * 140.0;
    const double step = kWidthStep * std::max(1.0, std::ceil(tries * pairs / kPairBudget));
    std::vector<Scored> found;
    for (int fi = 0; fi < static_cast<int>(c.frames.size()); ++fi)
        for (const int n1 : splits)
            for (const double spread : kSpreads) scan_split(c, Lattice{fi, n1, 0.0, 0.0, spread}, step, found);
    // Bands cut into rooms (a long narrow floor, rooms that only touch),
    // in coarser steps of width.
    std::vector<std::array<int, 3>> cut;  // n1, m1, m2
    for (int n1 = 0; n1 <= n && n <= kMaxCutRooms; ++n1)
        for (const int m1 : kCuts)
            for (const int m2 : kCuts) {
                const int rest = n - n1 * m1;
                if ((n1 == 0 && m1 > 1) || rest < 0 || (rest == 0 && m2 > 1) || rest % m2 != 0) continue;
                if (m1 > 1 || m2 > 1) cut.push_back({n1, m1, m2});
            }
    const double cut_tries = static_cast<double>(c.frames.size() * cut.size() * 2 * std::size(kReaches)) * 140.0;
    const double cut_step = 2 * kWidthStep * std::max(1.0, std::ceil(cut_tries * pairs / kPairBudget / 2));
    for (int fi = 0; fi < static_cast<int>(c.frames.size()); ++fi)
        for (const auto& [n1, m1, m2] : cut)
            for (const double spread : {kSpreads[0], kSpreads[1]})
                for (const double reach : kReaches)
                    scan_split(c, Lattice{fi, n1, 0.0, 0.0, spread, m1, m2, reach}, cut_step, found);
    return found;
}

}  // namespace

bool pair_allowed(const RoomGeom& a, const RoomGeom& b, const std::optional<double>& max_overlap) {
    const double shared = shared_area(a, b);
    if (shared <= kMinSharedArea) return true;
    const double smaller = std::min(a.area, b.area);
    const double limit = max_overlap                        ? *max_overlap
                         : smaller <= kSmallRoomArea - 1e-6 ? kSmallRoomLimit
                                                            : kLargeRoomLimit;
    return 100.0 * shared / smaller <= limit - 1e-4;
}

std::optional<Packing> pack_rooms(const PackRules& rules) {
    if (rules.area.size() > kPackMaxCorners || rules.rooms < 1) return std::nullopt;
    SplitMix rng{rules.seed * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull};
    Context c{rules, {}};
    for (const double a : frame_angles(rules.area, rng)) c.frames.push_back(make_frame(rules.area, a, rng));
    std::vector<Scored> found = scan(c);
    if (found.empty()) {  // no lattice fits: rooms one at a time
        std::vector<double> angles;
        for (const Frame& f : c.frames) angles.push_back(f.angle);
        for (int t = 0; t < kGreedyRestarts; ++t)
            if (std::optional<PackState> s = place_greedily(rules, angles, rng)) {
                improve(rules, *s, rng, kGreedyMovesPerRoom);
                if (auto joined = join_rooms(s->shapes, s->geoms, rng.next())) return joined;
            }
        return std::nullopt;
    }
    double best = 0.0;
    for (const Scored& s : found) best = std::max(best, s.area);
    std::vector<Scored> near;
    for (const Scored& s : found)
        if (s.area >= kNearBest * best) near.push_back(s);
    for (int t = 0; t < kJoinTries && !near.empty(); ++t) {
        const std::size_t pick = rng.next() % near.size();
        std::optional<PackState> start = lattice_layout(c, near[pick].lattice);
        near.erase(near.begin() + static_cast<std::ptrdiff_t>(pick));
        improve(rules, *start, rng);
        if (auto joined = join_rooms(start->shapes, start->geoms, rng.next())) return joined;
    }
    return std::nullopt;
}

}  // namespace impossible::design
