// The plan rasterised by our own code (for PNG files): every shape becomes
// filled polygons (design/plan_pieces.hpp: a stroke is a quad per segment
// plus round joins, a dashed segment a run of dashes), drawn
// with the even-odd rule (design/scanline.hpp) into an image 3 × 3 times
// larger, blended with each shape's alpha, then averaged down. Text is
// drawn as the rectangles of a segment font (image/text_rects.hpp).
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
#include "design/plan_pieces.hpp"
#include "design/scanline.hpp"

namespace impossible::design {
namespace {

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
            const bool big = !a.run && a.count > PolygonScan::kDirectEdges;
            if (a.last < y) {
                if (big) scans_.erase(a.piece);
                continue;
            }
            spans_.clear();
            if (a.run) {
                pieces_.runs[a.at].spans(y, width, a.near, spans_);
            } else if (big) {
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
        std::size_t at;  // its corners in corners_ (few corners only), or its run in Pieces::runs
        int last;
        float r, g, b, a;
        bool run;
        DashRun::Cursor near;  // a run's dashes near the row
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
        if (!a.run && a.count <= PolygonScan::kDirectEdges) {
            a.at = merged_corners_.size();
            merged_corners_.insert(merged_corners_.end(), corners, corners + a.count);
        }
        merged_.push_back(a);
    }

    void take_active(std::size_t k) { take(active_[k], active_[k].run ? nullptr : corners_.data() + active_[k].at); }

    void join(int y) {
        std::vector<std::uint32_t>& joined = starting_[y];
        if (joined.empty()) return;
        merged_.clear();
        merged_corners_.clear();
        std::size_t k = 0;
        for (const std::uint32_t i : joined) {
            const Piece& p = pieces_.list[i];
            const glm::dvec2* corners = p.run ? nullptr : pieces_.points.data() + p.first;
            if (!p.run && p.count > PolygonScan::kDirectEdges) scans_.emplace(i, PolygonScan(corners, p.count));
            for (; k < active_.size() && active_[k].piece < i; ++k) take_active(k);
            take({i, static_cast<std::uint32_t>(p.count), p.first, p.rows.last, p.r, p.g, p.b, p.a, p.run,
                  p.run ? pieces_.runs[p.first].start() : DashRun::Cursor{}},
                 corners);
        }
        for (; k < active_.size(); ++k) take_active(k);
        active_.swap(merged_);
        corners_.swap(merged_corners_);
        std::vector<std::uint32_t>().swap(joined);
    }
};

}  // namespace

image::Pixels plan_raster(const Drawing& d, double k_out) {
    image::Pixels image;
    image.channels = 3;
    const PlanSize size = plan_size(d, k_out);
    image.width = size.width;
    image.height = size.height;
    const int w = image.width * kPlanSuper, h = image.height * kPlanSuper;
    const Pieces pieces = plan_pieces(d, k_out * kPlanSuper, h);
    RowSweep sweep(pieces, h);
    std::vector<float> strip(static_cast<std::size_t>(w) * kPlanSuper * 3);
    RowScratch scratch;
    image.data.resize(static_cast<std::size_t>(image.width) * image.height * 3);
    for (int y = 0; y < image.height; ++y) {
        for (int sy = 0; sy < kPlanSuper; ++sy)
            draw_row(sweep.spans(y * kPlanSuper + sy, w), scratch, &strip[static_cast<std::size_t>(sy) * w * 3], w);
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) {
                float sum = 0.0f;
                for (int sy = 0; sy < kPlanSuper; ++sy)
                    for (int sx = 0; sx < kPlanSuper; ++sx)
                        sum += strip[(static_cast<std::size_t>(sy) * w + x * kPlanSuper + sx) * 3 + c];
                const float v = std::clamp(sum / (kPlanSuper * kPlanSuper), 0.0f, 1.0f);
                image.data[(static_cast<std::size_t>(y) * image.width + x) * 3 + c] = byte_of(v * 255.0f);
            }
    }
    return image;
}

}  // namespace impossible::design
