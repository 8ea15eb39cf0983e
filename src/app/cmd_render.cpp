// impossible render [LAYOUT] [options]: one side-by-side stereo frame.
#include <iostream>

#include "app/commands.hpp"
#include "cli/field_flags.hpp"
#include "cli/layout_source.hpp"
#include "cli/view_options.hpp"
#include "render/renderer.hpp"
#include "session/session.hpp"

namespace impossible::app {

namespace {

const char* kRenderHelp =
    "usage: impossible render [LAYOUT] [options]\n"
    "Renders one side-by-side stereo frame with the OpenGL rasteriser (the built-in default\n"
    "layout without LAYOUT) and writes it as PNG. --out and --ids are written together or not at\n"
    "all (a link is written through, a device such as /dev/stdout directly); naming one file twice,\n"
    "or a file the command reads (the layout, its textures, its models and their files), is a usage\n"
    "error. Portals that cover no pixel are not drawn; past --max-portal-passes the rest show the\n"
    "fill colour, with a warning.\n\n";

}  // namespace

int run_render_command(const Args& args, std::ostream& out, std::ostream& err) {
    const ViewTables tables = view_options();
    const ParsedArgs parsed = parse_args(args, 1, tables.own, tables.frame);
    if (parsed.help) {
        out << kRenderHelp << view_help(tables);
        return kExitOk;
    }
    const ViewOptions options = parse_view_options(parsed, tables);
    CommandOutputs outputs = frame_outputs(options);
    // frame_for makes it the session of the pairing at --path's --frame.
    session::Session session(load_layout_or_default(options.layout_path, outputs, err));
    const render::FrameDesc frame = frame_for(session, options);
    err << model_warnings_text(session)
        << light_options_warning(session, options.frame.light_depth, options.shadow_options);

    std::string fallback_note;
    const gl::Context context =
        value_or_throw(gl::create_context_with_fallback(options.backend, &fallback_note), "no OpenGL 4.5 context");
    if (!fallback_note.empty()) err << "note: " << fallback_note << "\n";

    render::Renderer renderer = value_or_throw(session.make_renderer(context.state()));
    const render::RenderedFrame result = value_or_throw(with_flags(renderer.render(frame)));

    const image::Image& image = result.image;
    write_frame_pngs(outputs, options, image.width, image.height, image.rgb, image.ids);
    if (options.stats) {
        const render::FrameStats& s = result.stats;
        err << "stats: draw_calls=" << s.draw_calls << " triangles=" << s.triangles
            << " portal_passes_drawn=" << s.portal_passes_drawn << " portal_passes_culled=" << s.portal_passes_culled
            << " portal_fills=" << s.portal_fills << " budget_fills=" << s.budget_fills
            << " max_level=" << s.max_level_reached << "\n";
    }
    if (result.stats.budget_fills > 0)
        err << "warning: the frame reached its budget of " << frame.max_portal_passes
            << " portal passes (--max-portal-passes); " << result.stats.budget_fills
            << " portals show the fill colour instead of what lies behind them\n";
    return kExitOk;
}

}  // namespace impossible::app
