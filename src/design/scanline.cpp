// Even-odd scanline filling; see scanline.hpp.
#include "design/scanline.hpp"

#include <algorithm>
#include <cmath>

namespace impossible::design {
namespace {

// floor or ceil of v as an int, clamped to lo..hi first (v may be huge).
int clamped(double v, int lo, int hi) {
    return static_cast<int>(std::clamp(v, static_cast<double>(lo), static_cast<double>(hi)));
}

}  // namespace

RowRange polygon_rows(const glm::dvec2* points, std::size_t count, int height) {
    if (count < 3 || height <= 0) return {};
    for (std::size_t i = 0; i < count; ++i)
        if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y)) return {};
    double top = points[0].y, bottom = points[0].y;
    for (std::size_t i = 0; i < count; ++i) top = std::min(top, points[i].y), bottom = std::max(bottom, points[i].y);
    return {clamped(std::floor(top), 0, height), clamped(std::ceil(bottom), -1, height - 1)};
}

PolygonScan::PolygonScan(const glm::dvec2* points, std::size_t count) : points_(points), count_(count) {
    for (std::size_t i = 0; i < count; ++i)
        if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y)) count_ = 0;  // nothing to fill
    if (count_ <= kDirectEdges) return;
    // Edge i runs from corner i to corner i - 1 (the last for i = 0).
    by_top_.resize(count);
    for (std::size_t i = 0; i < count; ++i) by_top_[i] = static_cast<std::uint32_t>(i);
    auto top = [&](std::uint32_t i) { return std::min(points[i].y, points[i ? i - 1 : count - 1].y); };
    std::sort(by_top_.begin(), by_top_.end(), [&](std::uint32_t a, std::uint32_t b) { return top(a) < top(b); });
}

namespace {

// The spans between pairs of sorted crossings.
void spans_of(const double* xs, std::size_t n, int width, std::vector<Span>& out) {
    for (std::size_t k = 0; k + 1 < n; k += 2) {
        const int x0 = clamped(std::ceil(xs[k] - 0.5), 0, width);
        const int x1 = std::min(clamped(std::ceil(xs[k + 1] - 0.5), 0, width) - 1, width - 1);
        if (x0 <= x1) out.push_back({x0, x1});
    }
}

// Where edge i (corner i to corner i - 1) crosses the line y = sy, if it does.
template <class Push>
inline void crossing(const glm::dvec2* points, std::size_t count, std::size_t i, double sy, Push push) {
    const glm::dvec2 a = points[i], b = points[i ? i - 1 : count - 1];
    if ((a.y > sy) != (b.y > sy)) push(a.x + (sy - a.y) * (b.x - a.x) / (b.y - a.y));
}

}  // namespace

void PolygonScan::direct_spans(const glm::dvec2* points, std::size_t count, int y, int width, std::vector<Span>& out) {
    const double sy = y + 0.5;
    double xs[kDirectEdges];
    std::size_t n = 0;
    for (std::size_t i = 0; i < count && i < kDirectEdges; ++i)
        crossing(points, count, i, sy, [&](double x) {
            // Insertion into the sorted crossings.
            std::size_t k = n++;
            for (; k > 0 && xs[k - 1] > x; --k) xs[k] = xs[k - 1];
            xs[k] = x;
        });
    spans_of(xs, n, width, out);
}

void PolygonScan::spans(int y, int width, std::vector<double>& xs, std::vector<Span>& out) {
    if (by_top_.empty()) return direct_spans(points_, count_, y, width, out);
    const double sy = y + 0.5;
    xs.clear();
    // An edge crosses the row exactly when its top is at or above the
    // centres and its bottom below them; once its bottom is passed it never
    // crosses again.
    auto end_y = [&](std::uint32_t i, bool top) {
        const double a = points_[i].y, b = points_[i ? i - 1 : count_ - 1].y;
        return top ? std::min(a, b) : std::max(a, b);
    };
    while (next_ < by_top_.size() && end_y(by_top_[next_], true) <= sy) active_.push_back(by_top_[next_++]);
    std::size_t kept = 0;
    for (const std::uint32_t i : active_) {
        if (end_y(i, false) <= sy) continue;
        crossing(points_, count_, i, sy, [&](double x) { xs.push_back(x); });
        active_[kept++] = i;
    }
    active_.resize(kept);
    std::sort(xs.begin(), xs.end());
    spans_of(xs.data(), xs.size(), width, out);
}

}  // namespace impossible::design
