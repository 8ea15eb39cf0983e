// Multisampling (FrameDesc::samples, `render --samples N`) against the
// supersampled tracer: the driver's sample positions are the tracer's
// pattern, the id map of a multisampled frame agrees with the tracer's
// centre-ray ids, and along portal edges (where the cell id changes) the
// resolved colour matches `trace --samples N`: no seam, no halo.
#include <algorithm>
#include <cstdio>
#include <string>

#include "cli/view_options.hpp"
#include "gl/gl.hpp"
#include "gl_fixture.hpp"
#include "image/compare.hpp"
#include "pose_cases.hpp"
#include "render/targets/multisample.hpp"
#include "trace/sample_pattern.hpp"
#include "trace/tracer.hpp"

namespace impossible {
namespace {

constexpr int kSamples = 4;  // llvmpipe's only multisample count

const char* const kLayouts[] = {"default.json",  "four_rooms.json",    "tunnel.json", "rotated.json",
                                "corridor.json", "corridor_wall.json", "loop.json",   "vr_study.json"};

render::FrameDesc start_frame(const layout::Layout& l, int samples) {
    render::FrameDesc f;
    f.head.position = l.start.position;
    f.head.yaw_deg = l.start.yaw_deg;
    f.head.roll_deg = 3.0;  // no edge exactly along the pixel grid
    f.room = l.start.room;
    f.eye_width = 160;
    f.eye_height = 90;
    f.samples = samples;
    return f;
}

bool offers(int samples) {
    const std::vector<int> counts = render::offered_sample_counts(render::DepthMode::ReversedZ);
    return std::find(counts.begin(), counts.end(), samples) != counts.end();
}

// Colour error of `a` against `b` on the pixels where `keys` changes between
// horizontal or vertical neighbours (both pixels of such a pair count).
struct EdgeError {
    long pixels = 0;
    double mean = 0.0;  // mean over edge pixels of the largest channel error
    long over = 0;      // edge pixels whose largest channel error exceeds the tolerance
    int worst = 0;
};

EdgeError edge_error(const image::Image& a, const image::Image& b, const std::vector<int>& ids, int tolerance) {
    EdgeError e;
    const int w = a.width, h = a.height;
    long sum = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t at = static_cast<size_t>(y) * w + x;
            const bool edge = (x > 0 && ids[at - 1] != ids[at]) || (x + 1 < w && ids[at + 1] != ids[at]) ||
                              (y > 0 && ids[at - w] != ids[at]) || (y + 1 < h && ids[at + w] != ids[at]);
            if (!edge) continue;
            int err = 0;
            for (int c = 0; c < 3; ++c) err = std::max(err, std::abs(int(a.rgb[3 * at + c]) - int(b.rgb[3 * at + c])));
            ++e.pixels;
            sum += err;
            e.over += err > tolerance;
            e.worst = std::max(e.worst, err);
        }
    e.mean = e.pixels ? static_cast<double>(sum) / e.pixels : 0.0;
    return e;
}

TEST(Multisample, DriverSamplePositionsAreTheTracersPattern) {
    Result<gl::Context> context = gl::create_context(gl::Backend::Egl);
    ASSERT_TRUE(context.has_value()) << context.error();
    if (!offers(kSamples)) GTEST_SKIP() << "the driver offers no 4-sample buffers";
    Result<render::Target> t = render::create_multisampled_target(8, 8, render::DepthMode::ReversedZ, kSamples);
    ASSERT_TRUE(t.has_value()) << t.error();
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, t->framebuffer.get());
    const std::span<const trace::SamplePosition> pattern = trace::sample_pattern(kSamples);
    for (int s = 0; s < kSamples; ++s) {
        GLfloat p[2] = {-1.0f, -1.0f};
        glGetMultisamplefv(GL_SAMPLE_POSITION, s, p);
        EXPECT_EQ(p[0], pattern[s].x) << "sample " << s;
        EXPECT_EQ(p[1], pattern[s].y) << "sample " << s;
    }
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    context->state().invalidate();
}

TEST(Multisample, ACountTheDriverLacksIsAClearError) {
    Result<gl::Context> context = gl::create_context(gl::Backend::Egl);
    ASSERT_TRUE(context.has_value()) << context.error();
    const std::vector<int> counts = render::offered_sample_counts(render::DepthMode::ReversedZ);
    ASSERT_FALSE(counts.empty());
    EXPECT_EQ(counts.front(), 1);
    int lacking = 0;
    for (int n : {2, 4, 8, 16})
        if (!offers(n)) lacking = n;
    if (!lacking) GTEST_SKIP() << "the driver offers every count";
    const layout::Layout l = testing::layout_from_file(std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/default.json");
    Result<render::Renderer> r = render::Renderer::create(context->state(), scene::build_scene(l));
    ASSERT_TRUE(r.has_value()) << r.error();
    const Result<render::RenderedFrame> frame = r->render(start_frame(l, lacking));
    ASSERT_FALSE(frame.has_value());
    EXPECT_NE(frame.error().find("offers"), std::string::npos) << frame.error();
    // The renderer still draws afterwards, multisampled or not.
    EXPECT_TRUE(r->render(start_frame(l, 1)).has_value());
}

// The frame of a pose case, at a size the tracer does quickly.
render::FrameDesc case_frame(const layout::Layout& l, const testing::PoseCase& c, int samples) {
    render::FrameDesc f;
    f.head = {c.position, c.yaw, c.pitch, c.roll};
    f.room = layout::find_room(l, c.room);
    f.eye_width = 200;
    f.eye_height = 120;
    f.samples = samples;
    return f;
}

// The frames the tests below look at: every pose case, and every layout's
// start with the head rolled 3° (so that no edge runs along the pixel grid).
std::vector<std::pair<std::string, render::FrameDesc>> frames_to_check(int samples) {
    std::vector<std::pair<std::string, render::FrameDesc>> out;
    for (const testing::PoseCase& c : testing::kPoseCases)
        out.emplace_back(std::string(c.layout) + ": " + c.what,
                         case_frame(testing::example_layout(c.layout), c, samples));
    for (const char* name : kLayouts)
        out.emplace_back(std::string(name) + ": start, rolled", start_frame(testing::example_layout(name), samples));
    return out;
}

std::string layout_of(const std::string& label) { return label.substr(0, label.find(':')); }

// Renders each of frames_to_check with a renderer of its layout and hands
// the label, frame, layout, renderer and multisampled image to `check`.
template <class Check>
void for_each_multisampled_frame(gl::Context& context, Check check) {
    for (const auto& [label, frame] : frames_to_check(kSamples)) {
        const layout::Layout l = testing::example_layout(layout_of(label).c_str());
        Result<render::Renderer> r = render::Renderer::create(context.state(), scene::build_scene(l));
        ASSERT_TRUE(r.has_value()) << r.error();
        const Result<render::RenderedFrame> ms = r->render(frame);
        ASSERT_TRUE(ms.has_value()) << ms.error();
        check(label, frame, l, *r, ms->image);
    }
}

// The id map of a multisampled frame against the tracer's centre rays, on
// every layout and pose (the corridor recursing 8 deep: the stencil works per
// sample). With the one-pixel edge tolerance the maps agree exactly except
// where no rule over four samples can know what the pixel centre shows
// (docs/accuracy.md, "Anti-aliasing"): a feature narrower than half a pixel
// that only centres hit (the depth-limit fill 8 portals down the corridor,
// two pixels wide), and an edge within 1/8 pixel of the centres of the
// image's outermost row, where the tolerance has no row beyond. Measured:
// 0 on 22 of these 25 frames, 2 to 4 pixels on three; asserted as the
// single-sample suite asserts, at most 0.01 %.
TEST(Multisample, IdsAgreeWithTheTracersCentreRays) {
    Result<gl::Context> context = gl::create_context(gl::Backend::Egl);
    ASSERT_TRUE(context.has_value()) << context.error();
    if (!offers(kSamples)) GTEST_SKIP() << "the driver offers no 4-sample buffers";
    for_each_multisampled_frame(*context, [](const std::string& label, const render::FrameDesc& frame,
                                             const layout::Layout& l, render::Renderer&, const image::Image& ms) {
        const image::Image centre = trace::trace_frame(l, cli::trace_desc_for(frame)).value();  // ids: centre rays
        const image::Comparison cmp = image::compare_pictures(ms, centre);
        std::printf("  %-56s ids %ld (%.4f%%)\n", label.c_str(), cmp.id_mismatches, cmp.id_mismatch_percent);
        EXPECT_LE(cmp.id_mismatch_percent, 0.01) << label;
    });
}

// Where each pixel's centre ray ends: its cell id and the portals it passed.
// Neighbours that differ here lie on either side of a portal's edge (or of a
// room's silhouette), even where a portal leads back into the same room.
std::vector<int> portal_keys(const layout::Layout& l, const trace::TraceDesc& desc) {
    const trace::Scene scene = trace::prepare_scene(l).value();
    std::vector<int> keys(static_cast<size_t>(2 * desc.eye_width) * desc.eye_height);
    for (int j = 0; j < desc.eye_height; ++j)
        for (int eye = 0; eye < 2; ++eye)
            for (int i = 0; i < desc.eye_width; ++i) {
                const trace::PixelRay ray = trace::pixel_ray(desc, eye, i, j);
                const trace::TraceHit hit = trace::trace_ray(scene, ray.origin, ray.dir, desc.room, desc.max_depth);
                keys[static_cast<size_t>(j) * 2 * desc.eye_width + eye * desc.eye_width + i] =
                    hit.id * 1024 + hit.portals_passed;
            }
    return keys;
}

// Along portal edges the multisampled colour matches the tracer with the
// same four sample positions: no seam (a line of a wrong colour, e.g. where
// the stencil of some samples was not marked) and no halo (a blend with a
// colour that is not there). Tolerance: a channel may differ by up to 48 of
// 255 on at most 1 % of the edge pixels, and by 6 on average: the rasteriser
// shades each pixel once, at its centre, where the tracer shades every
// sample, so pixels on an edge that also crosses a checker square or a
// shading step differ by part of that step. A seam would cost the full
// contrast of the edge on a whole line of pixels.
TEST(Multisample, PortalEdgesMatchTheSupersampledTracer) {
    Result<gl::Context> context = gl::create_context(gl::Backend::Egl);
    ASSERT_TRUE(context.has_value()) << context.error();
    if (!offers(kSamples)) GTEST_SKIP() << "the driver offers no 4-sample buffers";
    for_each_multisampled_frame(*context, [](const std::string& label, const render::FrameDesc& frame,
                                             const layout::Layout& l, render::Renderer& renderer,
                                             const image::Image& ms) {
        render::FrameDesc single_frame = frame;
        single_frame.samples = 1;
        const Result<render::RenderedFrame> single = renderer.render(single_frame);
        ASSERT_TRUE(single.has_value()) << single.error();

        trace::TraceDesc t = cli::trace_desc_for(frame);
        const std::vector<int> keys = portal_keys(l, t);
        const image::Image super = trace::trace_frame(l, t).value();
        const EdgeError edge = edge_error(ms, super, keys, 48);
        const EdgeError aliased = edge_error(single->image, super, keys, 48);
        std::printf("  %-56s %4ld edge pixels: 4x mean %5.2f worst %3d over %3ld | 1x mean %5.2f worst %3d over %3ld\n",
                    label.c_str(), edge.pixels, edge.mean, edge.worst, edge.over, aliased.mean, aliased.worst,
                    aliased.over);
        if (edge.pixels == 0) return;
        EXPECT_LE(edge.mean, 6.0) << label;
        EXPECT_LE(edge.over, edge.pixels / 100) << label;
        EXPECT_LT(edge.mean, aliased.mean) << label << ": multisampling should bring the edges closer";
    });
}

}  // namespace
}  // namespace impossible
