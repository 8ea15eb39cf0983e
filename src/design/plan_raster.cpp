// The plan rasterised by our own code (for PNG files): every shape becomes
// filled polygons (a stroke is a quad per segment plus round joins), drawn
// with the even-odd rule (design/scanline.hpp) into an image 3 × 3 times
// larger, blended with each shape's alpha, then averaged down. Text is left
// out.
//
// The larger image is never held whole: rows are drawn from the top, three
// at a time (one row of the output), with the polygons that reach them in
// drawing order, so memory is the output image, one strip and the polygons'
// corners. Every sub-pixel row starts white and sees the same blends in the
// same order as if the whole image were drawn polygon by polygon, so the
// result is the same bytes. Where many polygons cover a row (thousands of
// rooms on one spot), a run of pixels that the same polygons cover is
// blended once and copied, which gives each pixel the same value.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "design/plan.hpp"
#include "design/scanline.hpp"

namespace impossible::design {
namespace {

constexpr int kSuper = 3;
constexpr double kTitle = 28.0;  // px above the floor for the title, as plan_svg.cpp leaves

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

// One polygon to fill: its corners in Pieces::points, its colour, its rows.
struct Piece {
    std::size_t first = 0, count = 0;
    float r = 0, g = 0, b = 0, a = 0;
    RowRange rows;
};

// Every polygon of the drawing, in drawing order, in canvas pixels.
struct Pieces {
    std::vector<glm::dvec2> points;
    std::vector<Piece> list;

    void add(const math::Polygon2& poly, const Rgba& c, int height) {
        const Piece p{points.size(),
                      poly.size(),
                      static_cast<float>(c.r),
                      static_cast<float>(c.g),
                      static_cast<float>(c.b),
                      static_cast<float>(c.a),
                      polygon_rows(poly.data(), poly.size(), height)};
        if (p.rows.first > p.rows.last) return;  // covers no row
        points.insert(points.end(), poly.begin(), poly.end());
        list.push_back(p);
    }
};

Pieces pieces_of(const Drawing& d, double k, int height) {
    Pieces out;
    auto px = [&](glm::dvec2 p) { return glm::dvec2((p.x - d.min.x) * k, (p.y - d.min.y) * k + kTitle * kSuper); };
    for (const Shape& s : d.shapes) {
        if (s.kind == Shape::Kind::Text) continue;
        math::Polygon2 pts;
        for (const glm::dvec2& p : s.points) pts.push_back(px(p));
        if (s.kind == Shape::Kind::Fill) {
            out.add(pts, s.colour, height);
            continue;
        }
        Shape mapped = s;
        mapped.points = std::move(pts);
        for (const math::Polygon2& poly : stroke_polygons(mapped, k, 0.12 * k, 0.08 * k))
            out.add(poly, s.colour, height);
    }
    return out;
}

// A span of one row with its piece's colour.
struct RowSpan {
    int x0, x1;
    float r, g, b, a;
};

void blend(float* p, const RowSpan& c) {
    p[0] += c.a * (c.r - p[0]);
    p[1] += c.a * (c.g - p[1]);
    p[2] += c.a * (c.b - p[2]);
}

// std::lround of v in 0..255, inline: v - floor(v) is exact there.
std::uint8_t byte_of(float v) {
    const int i = static_cast<int>(v);
    return static_cast<std::uint8_t>(v - static_cast<float>(i) >= 0.5f ? i + 1 : i);
}

// Scratch space of draw_row.
struct RowScratch {
    std::vector<std::uint8_t> cut;  // per pixel (and one past): a span begins or ends before it
    std::vector<std::int32_t> run;  // per pixel: the run it lies in, -1 before the first
    std::vector<float> runs;        // per run: its colour
};

// One sub-pixel row, white, then every span blended in order: pixel by
// pixel, or, where that is less work, run by run, a run being the pixels
// between two neighbouring ends of spans (each pixel of a run sees the same
// blends, so gets the same value).
void draw_row(const std::vector<RowSpan>& spans, RowScratch& t, float* row, int width) {
    std::size_t pixels = 0;
    for (const RowSpan& s : spans) pixels += static_cast<std::size_t>(s.x1 - s.x0 + 1);
    if (spans.size() > 1 && pixels > 8 * spans.size() + static_cast<std::size_t>(width) / 4) {
        t.cut.assign(static_cast<std::size_t>(width) + 1, 0);
        for (const RowSpan& s : spans) t.cut[s.x0] = t.cut[s.x1 + 1] = 1;
        t.run.resize(static_cast<std::size_t>(width) + 1);
        std::int32_t run = -1;
        for (int x = 0; x <= width; ++x) t.run[x] = run += t.cut[x];
        std::size_t work = 0;  // runs blended
        for (const RowSpan& s : spans) work += static_cast<std::size_t>(t.run[s.x1 + 1] - t.run[s.x0]);
        if (work < pixels) {
            t.runs.assign(static_cast<std::size_t>(run + 1) * 3, 1.0f);
            for (const RowSpan& s : spans)
                for (std::int32_t r = t.run[s.x0]; r < t.run[s.x1 + 1]; ++r)
                    blend(&t.runs[static_cast<std::size_t>(r) * 3], s);
            for (int x = 0; x < width; ++x) {
                const std::int32_t r = t.run[x];
                const float* v = r < 0 ? nullptr : &t.runs[static_cast<std::size_t>(r) * 3];
                row[x * 3] = v ? v[0] : 1.0f, row[x * 3 + 1] = v ? v[1] : 1.0f, row[x * 3 + 2] = v ? v[2] : 1.0f;
            }
            return;
        }
    }
    std::fill(row, row + static_cast<std::size_t>(width) * 3, 1.0f);
    for (const RowSpan& s : spans)
        for (int x = s.x0; x <= s.x1; ++x) blend(row + x * 3, s);
}

// The polygons that reach the rows being drawn, in drawing order; a piece
// joins at its first row and leaves after its last. The corners of the
// pieces taking part are copied together in that order (a row reads them
// in one pass, not from all over the drawing); pieces of many corners keep
// a scan with an edge table instead.
class RowSweep {
public:
    RowSweep(const Pieces& pieces, int height) : pieces_(pieces), starting_(static_cast<std::size_t>(height)) {
        for (std::size_t i = 0; i < pieces.list.size(); ++i)
            starting_[pieces.list[i].rows.first].push_back(static_cast<std::uint32_t>(i));
    }

    // The spans of every piece on row y (rows in increasing order).
    const std::vector<RowSpan>& spans(int y, int width) {
        join(y);
        out_.clear();
        std::size_t kept = 0, kept_corners = 0;
        for (Active a : active_) {
            const bool big = a.count > PolygonScan::kDirectEdges;
            if (a.last < y) {
                if (big) scans_.erase(a.piece);
                continue;
            }
            spans_.clear();
            if (big) {
                scans_.at(a.piece).spans(y, width, xs_, spans_);
            } else {
                std::copy(corners_.begin() + static_cast<std::ptrdiff_t>(a.at),
                          corners_.begin() + static_cast<std::ptrdiff_t>(a.at + a.count),
                          corners_.begin() + static_cast<std::ptrdiff_t>(kept_corners));
                a.at = kept_corners;
                kept_corners += a.count;
                PolygonScan::direct_spans(corners_.data() + a.at, a.count, y, width, spans_);
            }
            for (const Span& s : spans_) out_.push_back({s.x0, s.x1, a.r, a.g, a.b, a.a});
            active_[kept++] = a;
        }
        active_.resize(kept);
        corners_.resize(kept_corners);
        return out_;
    }

private:
    struct Active {
        std::uint32_t piece, count;
        std::size_t at;  // its corners in corners_ (few corners only)
        int last;
        float r, g, b, a;
    };
    const Pieces& pieces_;
    std::vector<std::vector<std::uint32_t>> starting_;  // pieces by first row
    std::vector<Active> active_, merged_;               // in drawing order
    std::vector<glm::dvec2> corners_, merged_corners_;
    std::unordered_map<std::uint32_t, PolygonScan> scans_;
    std::vector<double> xs_;
    std::vector<Span> spans_;
    std::vector<RowSpan> out_;

    void take(Active a, const glm::dvec2* corners) {
        if (a.count <= PolygonScan::kDirectEdges) {
            a.at = merged_corners_.size();
            merged_corners_.insert(merged_corners_.end(), corners, corners + a.count);
        }
        merged_.push_back(a);
    }

    void join(int y) {
        std::vector<std::uint32_t>& joined = starting_[y];
        if (joined.empty()) return;
        merged_.clear();
        merged_corners_.clear();
        std::size_t k = 0;
        for (const std::uint32_t i : joined) {
            const Piece& p = pieces_.list[i];
            const glm::dvec2* corners = pieces_.points.data() + p.first;
            if (p.count > PolygonScan::kDirectEdges) scans_.emplace(i, PolygonScan(corners, p.count));
            for (; k < active_.size() && active_[k].piece < i; ++k) take(active_[k], corners_.data() + active_[k].at);
            take({i, static_cast<std::uint32_t>(p.count), 0, p.rows.last, p.r, p.g, p.b, p.a}, corners);
        }
        for (; k < active_.size(); ++k) take(active_[k], corners_.data() + active_[k].at);
        active_.swap(merged_);
        corners_.swap(merged_corners_);
        std::vector<std::uint32_t>().swap(joined);
    }
};

}  // namespace

image::Pixels plan_raster(const Drawing& d, double k_out) {
    image::Pixels image;
    image.channels = 3;
    image.width = static_cast<int>(std::ceil((d.max.x - d.min.x) * k_out));
    image.height = static_cast<int>(std::ceil((d.max.y - d.min.y) * k_out + kTitle));
    const int w = image.width * kSuper, h = image.height * kSuper;
    const Pieces pieces = pieces_of(d, k_out * kSuper, h);
    RowSweep sweep(pieces, h);
    std::vector<float> strip(static_cast<std::size_t>(w) * kSuper * 3);
    RowScratch scratch;
    image.data.resize(static_cast<std::size_t>(image.width) * image.height * 3);
    for (int y = 0; y < image.height; ++y) {
        for (int sy = 0; sy < kSuper; ++sy)
            draw_row(sweep.spans(y * kSuper + sy, w), scratch, &strip[static_cast<std::size_t>(sy) * w * 3], w);
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) {
                float sum = 0.0f;
                for (int sy = 0; sy < kSuper; ++sy)
                    for (int sx = 0; sx < kSuper; ++sx)
                        sum += strip[(static_cast<std::size_t>(sy) * w + x * kSuper + sx) * 3 + c];
                const float v = std::clamp(sum / (kSuper * kSuper), 0.0f, 1.0f);
                image.data[(static_cast<std::size_t>(y) * image.width + x) * 3 + c] = byte_of(v * 255.0f);
            }
    }
    return image;
}

}  // namespace impossible::design
