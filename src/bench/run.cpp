#include "bench/run.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>
#include <random>
#include <thread>
#include <tuple>

#include "cli/field_flags.hpp"
#include "cli/view_options.hpp"
#include "gl/gl.hpp"
#include "image/compare.hpp"
#include "render/renderer.hpp"
#include "session/field_error.hpp"
#include "trace/tracer.hpp"

namespace impossible::bench {

using cli::InputError;
using cli::trace_desc_for;
using cli::value_or_throw;
namespace {

using Clock = std::chrono::steady_clock;

double ms_between(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
}

render::FrameDesc frame_at(const BenchConfig& config, const BenchPose& pose) {
    render::FrameDesc f = config.frame;
    f.head = pose.head;
    f.room = pose.room;
    f.time = pose.time;
    f.hands = pose.hands;
    return f;
}

// A configuration's error text: empty when the frame was drawn. The
// renderer's message with its settings spelled as flags (--samples), but
// the setting a sweep varies in this configuration spelled as the sweep
// ("samples=8: not measured: --sweep samples 8: ...": no --samples was given).
std::string error_of(const Result<void>& drawn, const std::string& swept) {
    if (drawn) return {};
    if (swept.empty()) return cli::with_flags(drawn.error());
    const std::string swept_flag = swept == "depth" ? "--max-depth" : "--" + swept;
    return session::spell_fields(drawn.error(), [&](const std::string& field) {
        const std::string flag = cli::flag_of(field);
        return flag == swept_flag ? "--sweep " + swept : flag;
    });
}

// Passed samples per pixel sample: with multisampling, a query counts samples.
double pixels_of(const render::FrameDesc& f) { return 2.0 * f.eye_width * f.eye_height * f.samples; }

struct Measurer {
    const BenchPlan& plan;
    const std::vector<BenchPose>& poses;
    const BenchOptions& options;
    std::vector<std::vector<std::unique_ptr<render::Renderer>>> renderers;  // per stage of the walk, per layout variant
    std::vector<ConfigResult> results;

    // The variant's renderer with the pairing in force at the pose.
    render::Renderer& renderer_of(const BenchConfig& c, const BenchPose& pose) {
        return *renderers[static_cast<size_t>(pose.stage)][static_cast<size_t>(c.layout_variant)];
    }

    // The sweep's kind ("samples") for a configuration of the sweep, else "".
    std::string swept(const BenchConfig& c) const {
        const bool of_sweep = !options.sweep_items.empty() && c.group == options.sweep_items[0].kind;
        return of_sweep ? options.sweep_items[0].kind : std::string();
    }

    // Draws every configuration once, marking those the driver cannot do.
    // (Without culling a frame makes the passes it makes with culling: the
    // pixel rule and the budget bound both; docs/bounded-work.md.)
    void probe() {
        for (ConfigResult& r : results) {
            render::FrameStats stats;
            r.error =
                error_of(renderer_of(r.config, poses[0]).draw(frame_at(r.config, poses[0]), &stats), swept(r.config));
        }
        if (!results[0].error.empty()) throw InputError(results[0].error);
    }

    // Timed frames, configurations interleaved frame by frame so that machine
    // noise hits all of them alike. The order is shuffled every repetition
    // (fixed seed): a frame is slower right after a heavy one (llvmpipe's
    // memory and caches), so a fixed cyclic order would always charge the
    // configuration that follows the heaviest.
    void time_frames() {
        std::vector<size_t> order(results.size());
        for (size_t k = 0; k < order.size(); ++k) order[k] = k;
        std::mt19937 shuffle_rng(20261122u);
        for (int rep = -options.warmup; rep < options.frames; ++rep)
            for (size_t p = 0; p < poses.size(); ++p) {
                std::shuffle(order.begin(), order.end(), shuffle_rng);
                for (size_t k = 0; k < results.size(); ++k) {
                    ConfigResult& r = results[order[k]];
                    if (!r.error.empty()) continue;
                    render::FrameStats stats;
                    glFinish();
                    const Clock::time_point t0 = Clock::now();
                    r.error = error_of(renderer_of(r.config, poses[p]).draw(frame_at(r.config, poses[p]), &stats),
                                       swept(r.config));
                    const Clock::time_point t1 = Clock::now();
                    glFinish();
                    const Clock::time_point t2 = Clock::now();
                    if (rep < 0) continue;
                    r.submit_ms.push_back(ms_between(t0, t1));
                    r.frame_ms.push_back(ms_between(t0, t2));
                    if (rep > 0) continue;
                    const double n = static_cast<double>(poses.size());
                    r.draw_calls += stats.draw_calls / n;
                    r.triangles += stats.triangles / n;
                    r.portal_passes_drawn += stats.portal_passes_drawn / n;
                    r.portal_passes_culled += stats.portal_passes_culled / n;
                    r.portal_fills += stats.portal_fills / n;
                }
            }
    }

    // Profiled frames: colour fragments and per-portal subtree times.
    void profile_frames() {
        using Key = std::pair<int, int>;  // pose, portal
        std::vector<std::map<Key, std::vector<double>>> portal_ms(results.size());
        std::vector<std::map<Key, double>> portal_fragments(results.size());
        std::vector<std::vector<double>> frame_ms(results.size());
        for (int rep = 0; rep < options.profile_frames; ++rep)
            for (size_t p = 0; p < poses.size(); ++p)
                for (size_t c = 0; c < results.size(); ++c) {
                    ConfigResult& r = results[c];
                    if (!r.error.empty()) continue;
                    render::FrameDesc f = frame_at(r.config, poses[p]);
                    f.profile = true;
                    render::FrameStats stats;
                    glFinish();
                    const Clock::time_point t0 = Clock::now();
                    r.error = error_of(renderer_of(r.config, poses[p]).draw(f, &stats), swept(r.config));
                    glFinish();
                    frame_ms[c].push_back(ms_between(t0, Clock::now()));
                    for (const render::FrameStats::PortalCost& cost : stats.portal_costs) {
                        const Key key{static_cast<int>(p), cost.portal};
                        portal_ms[c][key].push_back(cost.ms);
                        portal_fragments[c][key] = cost.colour_fragments / pixels_of(f);
                    }
                    // Fragment counts do not change between repetitions.
                    if (rep == 0)
                        r.fragments_per_pixel +=
                            stats.colour_fragments / pixels_of(f) / static_cast<double>(poses.size());
                }
        for (size_t c = 0; c < results.size(); ++c) {
            ConfigResult& r = results[c];
            if (!frame_ms[c].empty()) r.profiled_frame_ms = spread_of(frame_ms[c]).median;
            for (const auto& [key, times] : portal_ms[c]) {
                PortalResult pr;
                pr.pose = key.first;
                pr.portal = plan.session_of(r.config.layout_variant, poses[static_cast<size_t>(key.first)].stage)
                                .layout()
                                .portals[key.second]
                                .id;
                pr.ms_median = spread_of(times).median;
                pr.fragments_per_pixel = portal_fragments[c][key];
                r.portals.push_back(pr);
            }
        }
    }

    // Each configuration's picture against the tracer's at the same pose and
    // size, with the reference depth: ids and colour PSNR, mean over poses.
    void compare_with_tracer() {
        // Per stage of the walk, per layout variant.
        std::vector<std::vector<trace::Scene>> scenes(plan.stages.size() + 1);
        for (std::size_t stage = 0; stage < scenes.size(); ++stage)
            for (std::size_t v = 0; v < plan.sessions.size(); ++v)
                scenes[stage].push_back(
                    value_or_throw(plan.session_of(static_cast<int>(v), static_cast<int>(stage)).make_trace_scene()));
        // One reference per layout variant, pose, size, light depth and
        // hidden-area mask (--sweep mask).
        std::map<std::tuple<int, size_t, int, int, int, bool>, image::Image> traced;
        const double n = static_cast<double>(poses.size());
        for (size_t p = 0; p < poses.size(); ++p)
            for (ConfigResult& r : results) {
                if (!r.error.empty()) continue;
                const render::FrameDesc f = frame_at(r.config, poses[p]);
                const auto key = std::make_tuple(r.config.layout_variant, p, f.eye_width, f.eye_height,
                                                 f.light_depth.value_or(-1), math::has_hidden_area(f));
                if (!traced.count(key)) {
                    trace::TraceDesc t = trace_desc_for(f);
                    t.max_depth = options.reference_depth;
                    t.samples = options.reference_samples;
                    traced[key] = value_or_throw(
                        trace::trace_frame(scenes[static_cast<size_t>(poses[p].stage)][r.config.layout_variant], t));
                }
                const image::Image& t = traced[key];
                Result<render::RenderedFrame> raster = renderer_of(r.config, poses[p]).render(f);
                if (!raster) {
                    r.error = error_of(Result<void>(Error{raster.error()}), swept(r.config));
                    continue;
                }
                const image::Comparison cmp = image::compare_pictures(raster->image, t);
                r.has_error = true;
                r.id_mismatch_percent += cmp.id_mismatch_percent / n;
                r.worst_id_mismatch_percent = std::max(r.worst_id_mismatch_percent, cmp.id_mismatch_percent);
                r.psnr_db += cmp.psnr_db / n;
            }
    }
};

}  // namespace

BenchResult run_bench(const BenchPlan& plan, const std::vector<BenchPose>& poses, const BenchOptions& options,
                      gl::StateCache& state, const std::string& gl_renderer) {
    Measurer m{plan, poses, options, {}, {}};
    m.renderers.resize(plan.stages.size() + 1);
    // One context: its renderers compile each program once.
    const render::SharedPrograms programs = render::make_shared_programs();
    for (std::size_t stage = 0; stage < m.renderers.size(); ++stage)
        for (std::size_t v = 0; v < plan.sessions.size(); ++v)
            m.renderers[stage].push_back(std::make_unique<render::Renderer>(value_or_throw(
                plan.session_of(static_cast<int>(v), static_cast<int>(stage)).make_renderer(state, programs))));
    for (const BenchConfig& c : plan.configs)
        m.results.push_back({c, {}, {}, {}, 0, 0, 0, 0, 0, 0, 0, {}, false, 0, 0, 0});
    m.probe();
    m.time_frames();
    m.profile_frames();
    if (options.error) m.compare_with_tracer();
    BenchResult out;
    out.gl_renderer = gl_renderer;
    out.cores = std::thread::hardware_concurrency();
    out.poses = static_cast<int>(poses.size());
    out.configs = std::move(m.results);
    return out;
}

}  // namespace impossible::bench
