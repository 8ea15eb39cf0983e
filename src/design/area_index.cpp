// Boxes inside a play area, through a grid of its edges; see area_index.hpp.
#include "design/area_index.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "design/scanline.hpp"

namespace impossible::design {
namespace {

// Whether the closed segment ab meets the closed box lo..hi (Liang and
// Barsky's clipping of the segment's parameter to each slab).
bool segment_meets_box(glm::dvec2 a, glm::dvec2 b, glm::dvec2 lo, glm::dvec2 hi) {
    double t0 = 0.0, t1 = 1.0;
    for (int axis = 0; axis < 2; ++axis) {
        const double p = a[axis], d = b[axis] - a[axis];
        if (d == 0.0) {
            if (p < lo[axis] || p > hi[axis]) return false;
            continue;
        }
        double u = (lo[axis] - p) / d, v = (hi[axis] - p) / d;
        if (u > v) std::swap(u, v);
        t0 = std::max(t0, u), t1 = std::min(t1, v);
        if (t0 > t1) return false;
    }
    return true;
}

// Where on segment ab the point nearest to p lies (0 at a, 1 at b).
double nearest_on_segment(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
    const glm::dvec2 d = b - a;
    const double length2 = glm::dot(d, d);
    return length2 > 0.0 ? std::clamp(glm::dot(p - a, d) / length2, 0.0, 1.0) : 0.0;
}

double cross(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

// Even-odd crossings of a ray from p towards +x.
bool inside_by_crossings(const math::Polygon2& poly, glm::dvec2 p) {
    bool inside = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        const glm::dvec2 &a = poly[i], &b = poly[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) inside = !inside;
    }
    return inside;
}

}  // namespace

AreaIndex::AreaIndex(math::Polygon2 area, bool force_index) : area_(std::move(area)) {
    turn_ = math::signed_area(area_) < 0.0 ? -1.0 : 1.0;
    indexed_ = area_.size() >= 3 && (force_index || area_.size() > kPlainCorners);
    if (indexed_) build();
}

void AreaIndex::build() {
    const std::size_t n = area_.size();
    glm::dvec2 lo = area_[0], hi = lo;
    for (const glm::dvec2& p : area_) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const int grid = std::clamp(static_cast<int>(std::sqrt(4.0 * static_cast<double>(n))), 8, 1024);
    origin_ = lo;
    cell_ = std::max({hi.x - lo.x, hi.y - lo.y, 1e-3}) / grid;
    nx_ = std::clamp(static_cast<int>(std::ceil((hi.x - lo.x) / cell_)), 1, grid + 1);
    nz_ = std::clamp(static_cast<int>(std::ceil((hi.y - lo.y) / cell_)), 1, grid + 1);
    math::Polygon2 local(n);  // in cells
    for (std::size_t i = 0; i < n; ++i) local[i] = (area_[i] - origin_) / cell_;
    // Each edge listed in every cell it passes within `m` cells of.
    constexpr double m = 1e-6;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> listed;  // (cell, edge)
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2 a = local[i], b = local[(i + 1) % n];
        const int r0 = std::clamp(static_cast<int>(std::floor(std::min(a.y, b.y) - m)), 0, nz_ - 1);
        const int r1 = std::clamp(static_cast<int>(std::floor(std::max(a.y, b.y) + m)), 0, nz_ - 1);
        for (int r = r0; r <= r1; ++r) {
            double t0 = 0.0, t1 = 1.0;
            if (a.y != b.y) {
                const double u = (r - m - a.y) / (b.y - a.y), v = (r + 1 + m - a.y) / (b.y - a.y);
                t0 = std::clamp(std::min(u, v), 0.0, 1.0), t1 = std::clamp(std::max(u, v), 0.0, 1.0);
            }
            const double x0 = a.x + t0 * (b.x - a.x), x1 = a.x + t1 * (b.x - a.x);
            const int c0 = std::clamp(static_cast<int>(std::floor(std::min(x0, x1) - m)), 0, nx_ - 1);
            const int c1 = std::clamp(static_cast<int>(std::floor(std::max(x0, x1) + m)), 0, nx_ - 1);
            for (int c = c0; c <= c1; ++c)
                listed.emplace_back(static_cast<std::uint32_t>(r * nx_ + c), static_cast<std::uint32_t>(i));
        }
    }
    const std::size_t cells = static_cast<std::size_t>(nx_) * nz_;
    start_.assign(cells + 1, 0);
    for (const auto& [cell, edge] : listed) ++start_[cell + 1];
    for (std::size_t c = 0; c < cells; ++c) start_[c + 1] += start_[c];
    edges_.resize(listed.size());
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (const auto& [cell, edge] : listed) edges_[fill[cell]++] = edge;
    // A cell no edge passes through lies wholly inside or outside: as its centre.
    state_.assign(cells, kOutside);
    PolygonScan scan(local.data(), n);
    std::vector<double> xs;
    std::vector<Span> spans;
    for (int r = 0; r < nz_; ++r) {
        spans.clear();
        scan.spans(r, nx_, xs, spans);
        for (const Span& s : spans)
            for (int c = s.x0; c <= s.x1; ++c) state_[static_cast<std::size_t>(r) * nx_ + c] = kInside;
    }
    for (std::size_t c = 0; c < cells; ++c)
        if (start_[c + 1] > start_[c]) state_[c] = kCrossed;
}

bool AreaIndex::box_inside(const glm::dvec2& lo, const glm::dvec2& hi) const {
    if (indexed_) return indexed_box_inside(lo, hi);
    return math::convex_inside(math::rectangle(lo, hi), area_, 1e-9);
}

bool AreaIndex::indexed_box_inside(const glm::dvec2& lo, const glm::dvec2& hi) const {
    const glm::dvec2 s_lo = lo + kEdgeClearance, s_hi = hi - kEdgeClearance;
    if (!(s_lo.x < s_hi.x && s_lo.y < s_hi.y)) return math::convex_inside(math::rectangle(lo, hi), area_, 1e-9);
    const glm::dvec2 g_hi = origin_ + glm::dvec2(nx_, nz_) * cell_;
    if (s_lo.x < origin_.x || s_lo.y < origin_.y || s_hi.x > g_hi.x || s_hi.y > g_hi.y) return false;
    auto cell_of = [&](double v, double o, int count) {
        return std::clamp(static_cast<int>(std::floor((v - o) / cell_)), 0, count - 1);
    };
    const int cx0 = std::max(0, cell_of(s_lo.x, origin_.x, nx_) - 1),
              cx1 = std::min(nx_ - 1, cell_of(s_hi.x, origin_.x, nx_) + 1);
    const int cz0 = std::max(0, cell_of(s_lo.y, origin_.y, nz_) - 1),
              cz1 = std::min(nz_ - 1, cell_of(s_hi.y, origin_.y, nz_) + 1);
    bool seen_inside = false;
    for (int cz = cz0; cz <= cz1; ++cz)
        for (int cx = cx0; cx <= cx1; ++cx) {
            const std::size_t c = static_cast<std::size_t>(cz) * nx_ + cx;
            if (state_[c] == kCrossed) {
                for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
                    ++edges_tested_;
                    const std::uint32_t e = edges_[k];
                    if (segment_meets_box(area_[e], area_[(e + 1) % area_.size()], s_lo, s_hi)) return false;
                }
                continue;
            }
            const glm::dvec2 c_lo = origin_ + glm::dvec2(cx, cz) * cell_, c_hi = c_lo + cell_;
            if (c_hi.x <= s_lo.x || c_lo.x >= s_hi.x || c_hi.y <= s_lo.y || c_lo.y >= s_hi.y) continue;
            if (state_[c] == kOutside) return false;
            seen_inside = true;
        }
    // No edge meets the shrunk box: it lies wholly inside or wholly outside.
    return seen_inside || inside_by_crossings(area_, 0.5 * (lo + hi));
}

void AreaIndex::nearest_edge(const glm::dvec2& p, std::uint32_t& edge, double& t) const {
    const std::size_t n = area_.size();
    double best = std::numeric_limits<double>::infinity();
    auto consider = [&](std::uint32_t e) {
        const glm::dvec2 a = area_[e], b = area_[(e + 1) % n];
        const double u = nearest_on_segment(a, b, p);
        const glm::dvec2 q = a + u * (b - a);
        const double d2 = glm::dot(p - q, p - q);
        if (d2 < best) best = d2, edge = e, t = u;
    };
    if (!indexed_) {
        for (std::uint32_t e = 0; e < n; ++e) consider(e);
        return;
    }
    const int cx = std::clamp(static_cast<int>(std::floor((p.x - origin_.x) / cell_)), 0, nx_ - 1);
    const int cz = std::clamp(static_cast<int>(std::floor((p.y - origin_.y) / cell_)), 0, nz_ - 1);
    for (int k = 0; k <= std::max(nx_, nz_); ++k) {
        for (int z = cz - k; z <= cz + k; ++z)
            for (int x = cx - k; x <= cx + k; ++x) {
                if (z < 0 || z >= nz_ || x < 0 || x >= nx_ || (std::abs(z - cz) != k && std::abs(x - cx) != k))
                    continue;
                const std::size_t c = static_cast<std::size_t>(z) * nx_ + x;
                for (std::uint32_t i = start_[c]; i < start_[c + 1]; ++i) consider(edges_[i]);
            }
        // An edge not met yet passes only through cells outside the block
        // of rings 0..k, which p lies in (or, outside the grid, beyond).
        const glm::dvec2 block_lo = origin_ + glm::dvec2(cx - k, cz - k) * cell_,
                         block_hi = origin_ + glm::dvec2(cx + k + 1, cz + k + 1) * cell_;
        const double out =
            std::max(0.0, std::min({p.x - block_lo.x, p.y - block_lo.y, block_hi.x - p.x, block_hi.y - p.y}));
        if (best <= out * out) return;
    }
}

double AreaIndex::signed_distance(const glm::dvec2& p) const {
    const std::size_t n = area_.size();
    std::uint32_t e = 0;
    double t = 0.0;
    nearest_edge(p, e, t);
    const glm::dvec2 a = area_[e], b = area_[(e + 1) % n];
    const glm::dvec2 q = a + t * (b - a);
    const double d = glm::length(p - q);
    bool inside = false;
    if (t > 0.0 && t < 1.0) {
        inside = turn_ * cross(b - a, p - a) > 0.0;  // the interior is on the edge's left (anticlockwise)
    } else {
        // Nearest to a corner: inside a convex corner means on the inner
        // side of both its edges, inside a reflex one of either.
        const std::size_t v = t <= 0.0 ? e : (e + 1) % n;
        const glm::dvec2 u = area_[(v + n - 1) % n], c = area_[v], w = area_[(v + 1) % n];
        const bool left_in = turn_ * cross(c - u, p - u) > 0.0, left_out = turn_ * cross(w - c, p - c) > 0.0;
        inside = turn_ * cross(c - u, w - c) > 0.0 ? left_in && left_out : left_in || left_out;
    }
    return inside ? d : -d;
}

}  // namespace impossible::design
