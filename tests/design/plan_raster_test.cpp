// The plan's rasteriser (design/plan_raster.cpp) draws three sub-pixel
// rows at a time with scanline fills (design/scanline.hpp); it must give
// the bytes the whole-canvas rasteriser it replaced gave (kept here as the
// reference, as it was), and a scanline fill must cover exactly the pixels
// whose centres a point test finds inside.
#include "design_test_util.hpp"

#include <algorithm>
#include <cmath>

#include "design/plan.hpp"
#include "design/report.hpp"
#include "design/scanline.hpp"
#include "design/tour.hpp"
#include "image/text_rects.hpp"

namespace design_test {
namespace {

// The rasteriser before the scanline one, whole canvas in memory.
constexpr int kRefSuper = 3;

struct RefCanvas {
    int w, h;
    std::vector<float> rgb;
    void fill(const math::Polygon2& poly, const design::Rgba& c) {  // poly in canvas pixels
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

math::Polygon2 ref_disc(glm::dvec2 c, double r) {
    math::Polygon2 out;
    for (int i = 0; i < 16; ++i)
        out.push_back(c + r * glm::dvec2(std::cos(i * math::kPi / 8), std::sin(i * math::kPi / 8)));
    return out;
}

// A stroke as polygons: segments (dashed ones cut into dashes) and joins.
// Opaque strokes get round joins; translucent ones none, so nothing is
// blended twice where pieces meet (they overlap at most at the joins).
std::vector<math::Polygon2> ref_stroke_polygons(const design::PlanShape& s, double k, double dash_on, double dash_off) {
    std::vector<math::Polygon2> out;
    const double half = std::max(0.5 * kRefSuper, 0.5 * s.width * k);
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
        if (s.colour.a >= 1.0 && half > kRefSuper) out.push_back(ref_disc(b, half));
    }
    return out;
}

// A line of text as the segment font's rectangles, its baseline at `at`.
void ref_text(RefCanvas& canvas, const design::PlanShape& s, glm::dvec2 at, double pixels) {
    const double scale = pixels / 10.0;
    const double width = std::max(0.0, static_cast<double>(image::text_width(s.text)) - 1.0) * scale;
    const glm::dvec2 origin{s.centred ? at.x - 0.5 * width : at.x, at.y - 7.0 * scale};
    for (const image::TextRect& r : image::text_rects(s.text)) {
        const glm::dvec2 lo = origin + glm::dvec2(r.x0, r.y0) * scale, hi = origin + glm::dvec2(r.x1, r.y1) * scale;
        canvas.fill({lo, {hi.x, lo.y}, hi, {lo.x, hi.y}}, s.colour);
    }
}

// Every shape, `k` canvas pixels a unit, each point through `px`.
template <class Px>
void ref_shapes(RefCanvas& canvas, const std::vector<design::PlanShape>& shapes, Px px, double k, double text_k,
                double dash_on, double dash_off, bool overlay) {
    for (const design::PlanShape& s : shapes) {
        math::Polygon2 pts;
        for (const glm::dvec2& p : s.points) pts.push_back(px(p));
        if (s.kind == design::PlanShape::Kind::Text) {
            ref_text(canvas, s, pts.front(), (overlay ? s.size : design::label_pixels(s, text_k)) * kRefSuper);
        } else if (s.kind == design::PlanShape::Kind::Fill) {
            canvas.fill(pts, s.colour);
        } else {
            design::PlanShape mapped = s;
            mapped.points = pts;
            for (const math::Polygon2& poly : ref_stroke_polygons(mapped, k, dash_on, dash_off))
                canvas.fill(poly, s.colour);
        }
    }
}

image::Pixels reference_raster(const design::Drawing& d, double k_out) {
    const double k = k_out * kRefSuper;
    const design::PlanSize size = design::plan_size(d, k_out);
    image::Pixels image;
    image.channels = 3;
    image.width = size.width;
    image.height = size.height;
    RefCanvas canvas{image.width * kRefSuper, image.height * kRefSuper, {}};
    canvas.rgb.assign(static_cast<std::size_t>(canvas.w) * canvas.h * 3, 1.0f);
    auto px = [&](glm::dvec2 p) {
        return glm::dvec2((p.x - d.min.x) * k, (p.y - d.min.y) * k + size.floor_top * kRefSuper);
    };
    ref_shapes(canvas, d.shapes, px, k, k_out, 0.12 * k, 0.08 * k, false);
    ref_shapes(
        canvas, design::plan_overlay(d, k_out), [](glm::dvec2 p) { return p * double(kRefSuper); }, kRefSuper, 1.0,
        5.0 * kRefSuper, 3.0 * kRefSuper, true);
    image.data.resize(static_cast<std::size_t>(image.width) * image.height * 3);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) {
                float sum = 0.0f;
                for (int sy = 0; sy < kRefSuper; ++sy)
                    for (int sx = 0; sx < kRefSuper; ++sx)
                        sum +=
                            canvas
                                .rgb[((static_cast<std::size_t>(y) * kRefSuper + sy) * canvas.w + x * kRefSuper + sx) *
                                         3 +
                                     c];
                const float v = std::clamp(sum / (kRefSuper * kRefSuper), 0.0f, 1.0f);
                image.data[(static_cast<std::size_t>(y) * image.width + x) * 3 + c] =
                    static_cast<std::uint8_t>(std::lround(v * 255.0f));
            }
    return image;
}

// Even-odd at the pixel's centre, with the crossings computed as the fill
// computes them: inside when an odd number lie at or left of the centre.
bool centre_inside(const math::Polygon2& poly, int x, int y) {
    const double sx = x + 0.5, sy = y + 0.5;
    int left = 0;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        const glm::dvec2 a = poly[i], b = poly[j];
        if ((a.y > sy) != (b.y > sy) && a.x + (sy - a.y) * (b.x - a.x) / (b.y - a.y) <= sx) ++left;
    }
    return left % 2 == 1;
}

math::Polygon2 star(int corners, glm::dvec2 centre, double outer, double inner) {
    math::Polygon2 out;
    for (int k = 0; k < corners; ++k) {
        const double a = 2.0 * math::kPi * k / corners + 0.1234, r = k % 2 ? inner : outer;
        out.push_back(centre + r * glm::dvec2(std::cos(a), std::sin(a)));
    }
    return out;
}

void expect_fill_matches_point_test(const math::Polygon2& poly, int width, int height) {
    const design::RowRange rows = design::polygon_rows(poly.data(), poly.size(), height);
    design::PolygonScan scan(poly.data(), poly.size());
    std::vector<double> xs;
    int inside = 0;
    for (int y = 0; y < height; ++y) {
        std::vector<char> filled(static_cast<std::size_t>(width), 0);
        if (y >= rows.first && y <= rows.last) {
            std::vector<design::Span> spans;
            scan.spans(y, width, xs, spans);
            for (std::size_t k = 0; k < spans.size(); ++k) {
                if (k > 0) {
                    EXPECT_GT(spans[k].x0, spans[k - 1].x1);  // left to right, apart
                }
                for (int x = spans[k].x0; x <= spans[k].x1; ++x) filled[x] = 1;
            }
        }
        for (int x = 0; x < width; ++x) {
            ASSERT_EQ(filled[x] == 1, centre_inside(poly, x, y)) << "pixel " << x << ", " << y;
            inside += filled[x];
        }
    }
    EXPECT_GT(inside, 0);
}

TEST(Scanline, AConcavePolygonCoversThePixelsWhoseCentresAreInside) {
    // An arrow-like concave heptagon (every edge tested on every row) and a
    // comb of 40 teeth (edge table), both partly off the image.
    const math::Polygon2 arrow = {{3.3, 10.2},  {60.7, 2.9},  {40.1, 30.6}, {95.4, 70.3},
                                  {30.2, 45.7}, {-8.6, 80.1}, {20.9, 33.3}};
    expect_fill_matches_point_test(arrow, 90, 75);
    math::Polygon2 comb = {{2.2, 70.7}, {2.2, 5.3}};
    for (int t = 0; t < 20; ++t) {
        comb.push_back({4.1 + 4.3 * t, 5.3});
        comb.push_back({5.9 + 4.3 * t, 60.1 - 1.7 * t});
    }
    comb.push_back({99.7, 70.7});
    ASSERT_GT(comb.size(), design::PolygonScan::kDirectEdges);
    expect_fill_matches_point_test(comb, 97, 83);
    expect_fill_matches_point_test(star(400, {50.3, 41.7}, 45.0, 20.0), 97, 83);
}

void expect_same_raster(const design::Drawing& d, double k) {
    const image::Pixels now = design::plan_raster(d, k), before = reference_raster(d, k);
    EXPECT_EQ(now.width, before.width);
    EXPECT_EQ(now.height, before.height);
    EXPECT_TRUE(now.data == before.data);
}

TEST(PlanRaster, TheBytesOfTheWholeCanvasRasteriser) {
    for (const char* name : {"default.json", "four_rooms.json", "rotated.json", "loop.json", "three_kinds.json"}) {
        SCOPED_TRACE(name);
        const layout::Layout l = load_file(name);
        const auto tour = design::plan_tour(l);
        const design::Drawing d =
            design::plan_drawing(l, design::make_report(l), tour ? tour->poses : std::vector<math::HeadPose>{});
        expect_same_raster(d, 37.0);
    }
}

TEST(PlanRaster, ManyRoomsOnOneSpotAndAPlayAreaOfManyCornersGiveTheSameBytes) {
    // 40 rooms on one spot: rows where drawing run by run is less work.
    std::string rooms;
    for (int i = 0; i < 40; ++i) rooms += (i ? ",\n" : "") + room("r" + std::to_string(i), 0.05 * i, 0, 3, 3);
    std::string polygon;
    for (const glm::dvec2& p : star(300, {1.5, 1.5}, 4.0, 3.0))
        polygon += (polygon.empty() ? "" : ", ") + ("[" + std::to_string(p.x) + ", " + std::to_string(p.y) + "]");
    const layout::Layout l = load("{ \"polygon\": [" + polygon + "] }", "r0", rooms, "");
    const design::Drawing d = design::plan_drawing(l, design::make_report(l), {});
    expect_same_raster(d, 41.0);
    expect_same_raster(d, 7.0);
}

}  // namespace
}  // namespace design_test
