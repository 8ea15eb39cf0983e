#include "trace/texture_sample.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace impossible::trace {

int wrap_texel(double i, int size, int wrap) {
    if (!std::isfinite(i)) return 0;
    const double n = size;
    double w = 0.0;
    if (wrap == assets::sampler_code::kClampToEdge) {
        w = std::clamp(i, 0.0, n - 1.0);
    } else if (wrap == assets::sampler_code::kMirroredRepeat) {
        const double m = i - 2.0 * n * std::floor(i / (2.0 * n));  // i mod 2·size, in [0, 2·size]
        w = m < n ? m : 2.0 * n - 1.0 - m;                         // = (size - 1) - mirror(m - size)
    } else {
        w = i - n * std::floor(i / n);  // i mod size
    }
    // The clamp only guards against a quotient rounded across a whole
    // number, which can happen for |i| beyond 2^52 / size.
    return static_cast<int>(std::clamp(w, 0.0, n - 1.0));
}

glm::dvec4 texel(const image::Pixels& image, int i, int j) {
    const std::size_t at = 4 * (static_cast<std::size_t>(j) * static_cast<std::size_t>(image.width) + i);
    const std::uint8_t* p = image.data.data() + at;
    return glm::dvec4(p[0], p[1], p[2], p[3]) / 255.0;
}

glm::dvec4 sample_mip0(const image::Pixels& image, const assets::Sampler& sampler, glm::dvec2 st) {
    const int w = image.width, h = image.height;
    if (w <= 0 || h <= 0 || image.data.size() < 4 * static_cast<std::size_t>(w) * static_cast<std::size_t>(h))
        return glm::dvec4(1.0);
    const double x = st.x * w, y = st.y * h;
    if (sampler.mag_filter == assets::sampler_code::kNearest) {
        return texel(image, wrap_texel(std::floor(x), w, sampler.wrap_s), wrap_texel(std::floor(y), h, sampler.wrap_t));
    }
    const double x0 = std::floor(x - 0.5), y0 = std::floor(y - 0.5);
    const double a = (x - 0.5) - x0, b = (y - 0.5) - y0;  // weights of the second texel on each axis
    const int i0 = wrap_texel(x0, w, sampler.wrap_s), i1 = wrap_texel(x0 + 1.0, w, sampler.wrap_s);
    const int j0 = wrap_texel(y0, h, sampler.wrap_t), j1 = wrap_texel(y0 + 1.0, h, sampler.wrap_t);
    return (1.0 - a) * (1.0 - b) * texel(image, i0, j0) + a * (1.0 - b) * texel(image, i1, j0) +
           (1.0 - a) * b * texel(image, i0, j1) + a * b * texel(image, i1, j1);
}

}  // namespace impossible::trace
