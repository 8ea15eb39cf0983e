// Hidden-area masks (see hidden_area.hpp).
#include "math/hidden_area.hpp"

#include <algorithm>
#include <cstddef>

namespace impossible::math {

namespace {

// The x (pixel units) where each edge of `visible` crosses the row through
// centres at y (pixel units), in edge order.
std::vector<double> row_crossings(const Polygon2& visible, int width, int height, double y) {
    std::vector<double> xs;
    const std::size_t n = visible.size();
    for (std::size_t k = 0; k < n; ++k) {
        const glm::dvec2 a{visible[k].x * width, visible[k].y * height};
        const glm::dvec2 b{visible[(k + 1) % n].x * width, visible[(k + 1) % n].y * height};
        if ((a.y > y) == (b.y > y)) continue;
        xs.push_back(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
    }
    return xs;
}

}  // namespace

bool pixel_hidden(const Polygon2& visible, int width, int height, int i, int j) {
    if (visible.size() < 3) return false;
    const double x = i + 0.5;
    int right = 0;
    for (double c : row_crossings(visible, width, height, j + 0.5))
        if (c > x) ++right;
    return right % 2 == 0;
}

std::vector<std::uint8_t> hidden_pixels(const Polygon2& visible, int width, int height) {
    const std::size_t w = static_cast<std::size_t>(width);
    std::vector<std::uint8_t> out(w * static_cast<std::size_t>(height), 0);
    if (visible.size() < 3) return out;
    for (int j = 0; j < height; ++j) {
        std::vector<double> xs = row_crossings(visible, width, height, j + 0.5);
        std::sort(xs.begin(), xs.end());
        // Crossings right of the centre: those after the last one at or left of it.
        std::size_t left = 0;
        for (int i = 0; i < width; ++i) {
            const double x = i + 0.5;
            while (left < xs.size() && !(xs[left] > x)) ++left;
            out[static_cast<std::size_t>(j) * w + static_cast<std::size_t>(i)] = (xs.size() - left) % 2 == 0 ? 1 : 0;
        }
    }
    return out;
}

}  // namespace impossible::math
