// The plan rasterised by our own code (for PNG files): every shape becomes
// filled polygons (a stroke is a quad per segment plus round joins), drawn
// with the even-odd rule into an image 3 × 3 times larger, blended with
// each shape's alpha, then averaged down. Text is left out.
#include <algorithm>
#include <cmath>

#include "design/plan.hpp"

namespace impossible::design {
namespace {

constexpr int kSuper = 3;

struct Canvas {
    int w, h;
    std::vector<float> rgb;
    void fill(const math::Polygon2& poly, const Rgba& c) {  // poly in canvas pixels
        if (poly.size() < 3) return;
        double top = poly[0].y, bottom = poly[0].y;
        for (const glm::dvec2& p : poly) top = std::min(top, p.y), bottom = std::max(bottom, p.y);
        const int y0 = std::max(0, static_cast<int>(std::floor(top))),
                  y1 = std::min(h - 1, static_cast<int>(std::ceil(bottom)));
        std::vector<double> xs;
        for (int y = y0; y <= y1; ++y) {
            const double sy = y + 0.5;
            xs.clear();
            for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
                const glm::dvec2 a = poly[i], b = poly[j];
                if ((a.y > sy) != (b.y > sy)) xs.push_back(a.x + (sy - a.y) * (b.x - a.x) / (b.y - a.y));
            }
            std::sort(xs.begin(), xs.end());
            for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
                const int x0 = std::max(0, static_cast<int>(std::ceil(xs[k] - 0.5)));
                const int x1 = std::min(w - 1, static_cast<int>(std::ceil(xs[k + 1] - 0.5)) - 1);
                for (int x = x0; x <= x1; ++x) {
                    float* p = &rgb[(static_cast<std::size_t>(y) * w + x) * 3];
                    const float a = static_cast<float>(c.a);
                    p[0] += a * (static_cast<float>(c.r) - p[0]);
                    p[1] += a * (static_cast<float>(c.g) - p[1]);
                    p[2] += a * (static_cast<float>(c.b) - p[2]);
                }
            }
        }
    }
};

math::Polygon2 disc(glm::dvec2 c, double r) {
    math::Polygon2 out;
    for (int i = 0; i < 16; ++i)
        out.push_back(c + r * glm::dvec2(std::cos(i * math::kPi / 8), std::sin(i * math::kPi / 8)));
    return out;
}

// A stroke as polygons: segments (dashed ones cut into dashes) and joins.
// Opaque strokes get round joins; translucent ones none, so nothing is
// blended twice where pieces meet (they overlap at most at the joins).
std::vector<math::Polygon2> stroke_polygons(const Shape& s, double k, double dash_on, double dash_off) {
    std::vector<math::Polygon2> out;
    const double half = std::max(0.5 * kSuper, 0.5 * s.width * k);
    std::vector<glm::dvec2> pts = s.points;
    if (s.closed && !pts.empty()) pts.push_back(pts.front());
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
        const glm::dvec2 a = pts[i], b = pts[i + 1];
        const double length = glm::distance(a, b);
        if (length < 1e-9) continue;
        const glm::dvec2 dir = (b - a) / length, side = glm::dvec2(-dir.y, dir.x) * half;
        const double period = s.dashed ? dash_on + dash_off : length;
        for (double t = 0.0; t < length; t += period) {
            const glm::dvec2 p = a + dir * t, q = a + dir * std::min(length, t + (s.dashed ? dash_on : length));
            out.push_back({p + side, q + side, q - side, p - side});
        }
        if (s.colour.a >= 1.0 && half > kSuper) out.push_back(disc(b, half));
    }
    return out;
}

}  // namespace

image::Pixels plan_raster(const Drawing& d, double k_out) {
    const double k = k_out * kSuper;
    constexpr double kTitle = 28.0;  // as plan_svg.cpp leaves for the title
    image::Pixels image;
    image.channels = 3;
    image.width = static_cast<int>(std::ceil((d.max.x - d.min.x) * k_out));
    image.height = static_cast<int>(std::ceil((d.max.y - d.min.y) * k_out + kTitle));
    Canvas canvas{image.width * kSuper, image.height * kSuper, {}};
    canvas.rgb.assign(static_cast<std::size_t>(canvas.w) * canvas.h * 3, 1.0f);
    auto px = [&](glm::dvec2 p) { return glm::dvec2((p.x - d.min.x) * k, (p.y - d.min.y) * k + kTitle * kSuper); };
    for (const Shape& s : d.shapes) {
        if (s.kind == Shape::Kind::Text) continue;
        math::Polygon2 pts;
        for (const glm::dvec2& p : s.points) pts.push_back(px(p));
        if (s.kind == Shape::Kind::Fill) {
            canvas.fill(pts, s.colour);
            continue;
        }
        Shape mapped = s;
        mapped.points = pts;
        for (const math::Polygon2& poly : stroke_polygons(mapped, k, 0.12 * k, 0.08 * k)) canvas.fill(poly, s.colour);
    }
    image.data.resize(static_cast<std::size_t>(image.width) * image.height * 3);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) {
                float sum = 0.0f;
                for (int sy = 0; sy < kSuper; ++sy)
                    for (int sx = 0; sx < kSuper; ++sx)
                        sum +=
                            canvas.rgb[((static_cast<std::size_t>(y) * kSuper + sy) * canvas.w + x * kSuper + sx) * 3 +
                                       c];
                const float v = std::clamp(sum / (kSuper * kSuper), 0.0f, 1.0f);
                image.data[(static_cast<std::size_t>(y) * image.width + x) * 3 + c] =
                    static_cast<std::uint8_t>(std::lround(v * 255.0f));
            }
    return image;
}

}  // namespace impossible::design
