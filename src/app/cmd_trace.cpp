// impossible trace [LAYOUT] [options]: the same frame as `render`, computed by
// the CPU reference ray tracer (src/trace, docs/tracer.md).
#include <algorithm>
#include <chrono>
#include <iostream>
#include <optional>
#include <thread>

#include "app/commands.hpp"
#include "cli/layout_source.hpp"
#include "cli/view_options.hpp"
#include "session/session.hpp"
#include "trace/portal_rays.hpp"
#include "trace/tracer.hpp"

namespace impossible::app {

namespace {

const char* kTraceHelp =
    "usage: impossible trace [LAYOUT] [options]\n"
    "Computes one side-by-side stereo frame with the CPU reference ray tracer (double precision,\n"
    "rays followed through portals) for the same view as `impossible render`, and writes it as\n"
    "PNG. It is the accuracy oracle for the rasteriser: compare the two with `impossible compare`.\n"
    "The options are render's; --backend, --stereo, --clip and --no-cull only matter to the\n"
    "rasteriser and are accepted and ignored. --max-portal-passes bounds each pixel's ray tree\n"
    "(each sample's): past it, the rest of its portals show the fill colour, with a warning.\n"
    "--stats prints rays per second instead.\n"
    "--portal-rays N prints on stderr `portal_rays: ID ...`, the portals that every N-th pixel-centre\n"
    "ray of both eyes reaches through portals only (room faces and props ignored; a brute force of\n"
    "walk's seen test, docs/changes.md), with --path the pairing frame K started with.\n\n";

// What trace takes besides the view options.
struct TraceOptions {
    int threads = 0;      // 0: every core
    int portal_rays = 0;  // > 0: print the portals the pixel rays reach, every this many pixels
};

constexpr Option<TraceOptions> kTraceOptions[] = {
    {"--threads", "N", "threads to trace with (default: every core)",
     [](TraceOptions& o, const OptionValue& v) { o.threads = parse_int(v.name, v.text, 1, 256); }},
    {"--portal-rays", "N",
     "print the portals every N-th pixel ray reaches through portals only, faces and props ignored "
     "(with --path: the pairing frame K started with)",
     [](TraceOptions& o, const OptionValue& v) { o.portal_rays = parse_int(v.name, v.text, 1, 1 << 15); }},
};

// `portal_rays: ID ...`: the portals of `session`'s layout that the pixel
// rays of `view` reach (trace/portal_rays.hpp), every `step`-th pixel.
void print_portal_rays(const session::Session& session, const math::View& view, int step, std::ostream& err) {
    const trace::Scene scene = value_or_throw(session.make_trace_scene());
    const trace::PortalRays rays = trace::portal_rays(scene, view, step);
    err << "portal_rays:";
    for (std::size_t k = 0; k < rays.reached.size(); ++k)
        if (rays.reached[k]) err << ' ' << session.layout().portals[k].id;
    err << "\n";
}

}  // namespace

int run_trace_command(const Args& args, std::ostream& out, std::ostream& err) {
    const ViewTables tables = trace_view_options();
    const ParsedArgs parsed = parse_args(args, 1, tables.own, tables.frame, kTraceOptions);
    if (parsed.help) {
        out << kTraceHelp << view_help(tables) << options_help(kTraceOptions, kViewHelpColumn);
        return kExitOk;
    }
    const ViewOptions options = parse_view_options(parsed, tables);
    CommandOutputs outputs = frame_outputs(options);
    TraceOptions own;
    apply_options(kTraceOptions, parsed, own);
    const int threads = own.threads;
    // frame_for makes it the session of the pairing at --path's --frame.
    session::Session session(load_layout_or_default(options.layout_path, outputs, err));
    std::optional<session::Session> started;  // --portal-rays: the pairing the frame started with
    if (own.portal_rays > 0) started = cli::session_frame_started_with(session, options);
    const render::FrameDesc frame = frame_for(session, options);
    err << model_warnings_text(session) << light_options_warning(session, options.frame.light_depth, false);

    const trace::TraceDesc desc = trace_desc_for(frame, threads);

    const auto start = std::chrono::steady_clock::now();
    const trace::Scene scene = value_or_throw(session.make_trace_scene());
    trace::TraceStats cut;
    const image::Image image = value_or_throw(trace::trace_frame(scene, desc, &cut));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    write_frame_pngs(outputs, options, image.width, image.height, image.rgb, image.ids);
    if (started) print_portal_rays(*started, frame, own.portal_rays, err);
    if (options.stats) {
        const long rays = static_cast<long>(image.width) * image.height;
        long fills = 0, nothing = 0;
        for (std::uint8_t id : image.ids) {
            fills += id == shading::kFillId;
            nothing += id == trace::kIdNothing;
        }
        const int used = threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
        err << "stats: rays=" << rays << " seconds=" << seconds
            << " rays_per_s=" << (seconds > 0.0 ? static_cast<long>(rays / seconds) : 0) << " threads=" << used
            << " fill_pixels=" << fills << " empty_pixels=" << nothing << " budget_rays=" << cut.budget_rays
            << " budget_fills=" << cut.budget_fills << "\n";
    }
    if (cut.budget_fills > 0)
        err << "warning: " << cut.budget_rays << " ray trees reached their budget of " << desc.max_portal_passes
            << " portal passes each (--max-portal-passes); " << cut.budget_fills
            << " portals show the fill colour instead of what lies behind them\n";
    return kExitOk;
}

}  // namespace impossible::app
