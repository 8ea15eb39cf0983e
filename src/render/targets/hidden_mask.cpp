// A headset's hidden-area mask in the stencil (hidden_mask.hpp).
//
// The hidden pixels of each eye are runs along its rows (math::hidden_pixels).
// Drawn as one rectangle per run, a curved boundary costs a rectangle per row
// (about 4,000 for a 2064x2208 pair; llvmpipe took 35-45 ms for them, more
// than the mask saved), so consecutive rows with as many runs are covered by
// trapezoids instead: each slanted side passes, at every row's pixel centres,
// strictly between the last hidden and the first visible centre (within
// kCentreTolerance of the run's pixel boundary), so the trapezoid covers
// exactly the rows' hidden pixel centres. Multisampled, the side must also
// pass between the samples (within kSampleTolerance at both row edges). The
// horizontal sides lie on row boundaries, between centres.
#include "render/targets/hidden_mask.hpp"

#include <algorithm>
#include <cmath>

#include "math/hidden_area.hpp"
#include "render/programs/scene_program.hpp"

namespace impossible::render {

namespace {

// Pixels: a side's distance from the run's boundary at a row centre, and
// (multisampled) at the row's edges, leaving room for the rasteriser's
// 1/256-pixel snapping and for sample offsets of up to 7/16 pixel.
constexpr double kCentreTolerance = 0.5 - 1.0 / 32.0;
constexpr double kSampleTolerance = 0.5 - 7.0 / 16.0 - 1.0 / 64.0;

Result<gl::Program> build_mask_program() {
    const std::vector<gl::ShaderSource> stages = {embedded_shader(GL_VERTEX_SHADER, "shaders/hidden_mask.vert.glsl"),
                                                  embedded_shader(GL_FRAGMENT_SHADER, "shaders/hidden_mask.frag.glsl")};
    return gl::build_program(stages, "");
}

// One eye's hidden runs, [begin, end) columns, per image row from the top.
using RowRuns = std::vector<std::vector<std::array<int, 2>>>;

RowRuns runs_of(const std::vector<std::uint8_t>& hidden, int w, int h) {
    RowRuns rows(static_cast<size_t>(h));
    for (int j = 0; j < h; ++j) {
        const std::uint8_t* row = &hidden[static_cast<size_t>(j) * w];
        for (int i = 0; i < w;) {
            if (!row[i]) {
                ++i;
                continue;
            }
            int end = i;
            while (end < w && row[end]) ++end;
            rows[static_cast<size_t>(j)].push_back({i, end});
            i = end;
        }
    }
    return rows;
}

// The line through (a + 0.5, first) and (c - 0.5, last) in (row, column):
// its column at row coordinate y.
struct Side {
    double y0 = 0, x0 = 0, slope = 0;
    double at(double y) const { return x0 + slope * (y - y0); }
};

Side side_through(double first_row, double first, double last_row, double last) {
    const double dy = last_row - first_row;
    return {first_row, first, dy > 0 ? (last - first) / dy : 0.0};
}

// Whether `side` passes each row j of [a, c) at its boundary b(j).
template <class Boundary>
bool side_fits(const Side& side, int a, int c, Boundary b, bool multisample) {
    for (int j = a; j < c; ++j) {
        const double x = b(j);
        if (multisample) {
            if (std::abs(side.at(j) - x) > kSampleTolerance || std::abs(side.at(j + 1.0) - x) > kSampleTolerance)
                return false;
        } else if (std::abs(side.at(j + 0.5) - x) > kCentreTolerance) {
            return false;
        }
    }
    return true;
}

// The trapezoids over rows [a, c) of run k (rows of the same run count),
// appended as triangles in pixel coordinates (x from the eye's left edge,
// y image rows from the top).
struct Trapezoids {
    const RowRuns& runs;
    bool multisample = false;
    std::vector<double>& xy;

    bool fits(int a, int c, size_t k, Side& left, Side& right) const {
        const auto begin = [&](int j) { return static_cast<double>(runs[static_cast<size_t>(j)][k][0]); };
        const auto end = [&](int j) { return static_cast<double>(runs[static_cast<size_t>(j)][k][1]); };
        left = side_through(a + 0.5, begin(a), c - 0.5, begin(c - 1));
        right = side_through(a + 0.5, end(a), c - 0.5, end(c - 1));
        // Proper quadrilaterals only: the sides do not cross within [a, c].
        if (!(right.at(a) > left.at(a) && right.at(c) > left.at(c))) return false;
        return side_fits(left, a, c, begin, multisample) && side_fits(right, a, c, end, multisample);
    }

    void add(int a, int c, size_t k) {
        int last = a + 1;
        Side left, right, l, r;
        fits(a, last, k, left, right);  // one row always fits: vertical sides on the boundaries
        while (last < c && fits(a, last + 1, k, l, r)) {
            ++last;
            left = l;
            right = r;
        }
        xy.insert(xy.end(), {left.at(a), double(a), right.at(a), double(a), right.at(last), double(last)});
        xy.insert(xy.end(), {left.at(a), double(a), right.at(last), double(last), left.at(last), double(last)});
        if (last < c) add(last, c, k);
    }
};

// Each eye's trapezoids in the target's NDC, and its visible spans.
std::vector<float> build_triangles(HiddenMask& mask, const std::array<math::EyeOptics, 2>& optics, int w, int h,
                                   bool multisample) {
    std::vector<float> out;
    for (int e = 0; e < 2; ++e) {
        const std::vector<std::uint8_t> hidden = math::hidden_pixels(optics[static_cast<size_t>(e)].visible_area, w, h);
        const RowRuns runs = runs_of(hidden, w, h);
        std::vector<std::array<int, 2>>& spans = mask.rows[static_cast<size_t>(e)];
        spans.assign(static_cast<size_t>(h), {w, -1});
        for (int j = 0; j < h; ++j)
            for (int i = 0; i < w; ++i)
                if (!hidden[static_cast<size_t>(j) * w + i]) {
                    spans[static_cast<size_t>(j)][0] = std::min(spans[static_cast<size_t>(j)][0], i);
                    spans[static_cast<size_t>(j)][1] = i;
                }
        std::vector<double> xy;
        Trapezoids t{runs, multisample, xy};
        for (int a = 0; a < h;) {
            int c = a + 1;
            while (c < h && runs[static_cast<size_t>(c)].size() == runs[static_cast<size_t>(a)].size()) ++c;
            for (size_t k = 0; k < runs[static_cast<size_t>(a)].size(); ++k) t.add(a, c, k);
            a = c;
        }
        // Pixels → the side-by-side target's NDC (y up).
        for (size_t v = 0; v + 1 < xy.size(); v += 2) {
            out.push_back(static_cast<float>((e * w + xy[v]) / w - 1.0));
            out.push_back(static_cast<float>(1.0 - 2.0 * xy[v + 1] / h));
        }
    }
    return out;
}

}  // namespace

Result<void> prepare_hidden_mask(HiddenMask& mask, const math::View& frame, int samples) {
    mask.active = false;
    if (!math::has_hidden_area(frame)) return {};
    const bool multisample = samples > 1;
    if (mask.optics != frame.eye_optics || mask.eye_width != frame.eye_width || mask.eye_height != frame.eye_height ||
        mask.multisample != multisample) {
        mask.optics = frame.eye_optics;
        mask.eye_width = frame.eye_width;
        mask.eye_height = frame.eye_height;
        mask.multisample = multisample;
        const std::vector<float> xy =
            build_triangles(mask, *frame.eye_optics, frame.eye_width, frame.eye_height, multisample);
        mask.vertex_count = static_cast<int>(xy.size() / 2);
        mask.vertices = {};
        mask.vertex_array = {};
        if (mask.vertex_count > 0) {
            mask.vertices = gl::create_buffer();
            glNamedBufferStorage(mask.vertices.get(), static_cast<GLsizeiptr>(xy.size() * sizeof(float)), xy.data(), 0);
            mask.vertex_array = gl::create_vertex_array();
            const GLuint vao = mask.vertex_array.get();
            glVertexArrayVertexBuffer(vao, 0, mask.vertices.get(), 0, 2 * sizeof(float));
            glVertexArrayAttribFormat(vao, 0, 2, GL_FLOAT, GL_FALSE, 0);
            glVertexArrayAttribBinding(vao, 0, 0);
            glEnableVertexArrayAttrib(vao, 0);
        }
    }
    if (mask.vertex_count == 0) return {};
    if (!mask.program.get()) {
        Result<gl::Program> built = build_mask_program();
        if (!built) return built;
        mask.program = std::move(*built);
    }
    mask.active = true;
    return {};
}

void draw_hidden_mask(gl::StateCache& state, const Target& target, const HiddenMask& mask, FrameStats& stats) {
    if (!mask.active) return;
    gl::PassState s;
    s.depth_test = false;
    s.depth_write = false;
    s.color_mask = gl::kColorNone;
    s.write_ids = false;
    s.cull_back_faces = false;
    s.stencil.enabled = true;
    s.stencil.func = GL_ALWAYS;
    s.stencil.pass = GL_REPLACE;
    state.apply(s, kHiddenStencil);
    state.no_scissor();
    state.draw_framebuffer(target.framebuffer.get());
    state.viewport({0, 0, target.width, target.height});
    state.program(mask.program.get());
    state.vertex_array(mask.vertex_array.get());
    glDrawArrays(GL_TRIANGLES, 0, mask.vertex_count);
    stats.draw_calls += 1;
}

bool meets_visible_area(const HiddenMask& mask, int eye, const NdcRect& rect, int samples) {
    if (!mask.active) return true;
    if (rect.empty()) return false;
    const int w = mask.eye_width, h = mask.eye_height;
    // Pixel centres (i + 0.5, j + 0.5) within the rectangle, with the margin
    // of covers_pixel_centre; a multisampled pixel counts if any of it does.
    const double grow = samples > 1 ? 1.0 : 1.0 / 256.0;
    const double x0 = (rect.x0 + 1.0) * 0.5 * w - grow, x1 = (rect.x1 + 1.0) * 0.5 * w + grow;
    const double top = (1.0 - rect.y1) * 0.5 * h - grow, bottom = (1.0 - rect.y0) * 0.5 * h + grow;
    const int i0 = std::max(0, static_cast<int>(std::ceil(x0 - 0.5)));
    const int i1 = std::min(w - 1, static_cast<int>(std::floor(x1 - 0.5)));
    const int j0 = std::max(0, static_cast<int>(std::ceil(top - 0.5)));
    const int j1 = std::min(h - 1, static_cast<int>(std::floor(bottom - 0.5)));
    const std::vector<std::array<int, 2>>& spans = mask.rows[static_cast<size_t>(eye)];
    for (int j = j0; j <= j1; ++j) {
        const std::array<int, 2>& s = spans[static_cast<size_t>(j)];
        if (s[0] <= s[1] && s[0] <= i1 && s[1] >= i0) return true;
    }
    return false;
}

}  // namespace impossible::render
