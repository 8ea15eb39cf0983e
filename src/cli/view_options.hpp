// The options that `render`, `trace` and `bench` share (cli.md), parsed into
// plain data, and how they become a frame description.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>

#include "cli/args.hpp"
#include "cli/frame_options.hpp"
#include "cli/option_table.hpp"
#include "cli/output_files.hpp"
#include "cli/technique_options.hpp"
#include "gl/context.hpp"
#include "layout/layout.hpp"
#include "render/frame.hpp"
#include "session/session.hpp"
#include "trace/tracer.hpp"

namespace impossible::cli {

// The options of render and trace: the frame's settings (FrameOptions, from
// the rows of cli/frame_options.hpp) and the command's own.
struct ViewOptions : FrameOptions {
    std::optional<std::string> layout_path;  // none: the built-in default
    std::optional<math::HeadPose> pose;
    std::optional<std::string> room;
    // --path FILE --frame K [--fps N]: the head, room, hands and time of
    // line K of a walk (instead of --pose, --room, --time and --hands).
    std::optional<std::string> path;
    std::optional<int> path_frame;
    std::optional<double> fps;
    std::string out = "stereo.png";
    std::optional<std::string> ids;
    std::optional<gl::Backend> backend;  // none: EGL, falling back to OSMesa
    bool stats = false;
};

// A command's option tables: its own rows, then the frame's.
struct ViewTables {
    OptionTable<ViewOptions> own;
    OptionTable<FrameOptions> frame;
};

// parse_args reads ViewTables as its two tables.
inline void add_option_names(ArgNames& names, const ViewTables& tables) {
    add_option_names(names, tables.own);
    add_option_names(names, tables.frame);
}

// render's tables (bench drops some of them), in the order of the help and
// of the checks.
ViewTables view_options();
// trace's: render's without the rasteriser's shadow maps (--shadow-size,
// --no-shadows); the tracer's shadows are exact.
ViewTables trace_view_options();
// The help's option list of the tables.
std::string view_help(const ViewTables& tables);

// The layout (the first positional argument) and the options of the tables
// that were given; throws InputError for a bad value.
ViewOptions parse_view_options(const ParsedArgs& args, const ViewTables& tables = view_options());

// The warning line (ending in '\n') for --light-depth (`light_depth` set)
// or the shadow options (`shadow_options`) on a layout whose lighting is
// "fixed", where they change nothing; on a lit layout, for a light depth
// (asked for, or the layout's) that gives more than lights::kMaxLightPaths
// light paths, which both renderers lower (docs/bounded-work.md); "" otherwise.
std::string light_options_warning(const session::Session& session, const std::optional<int>& light_depth,
                                  bool shadow_options);

// The layout's warnings about its glTF models (layout::Layout::model_warnings:
// alphaMode BLEND, dropped lights), "warning: " and '\n' around each, as
// validate prints them; "" without any.
std::string model_warnings_text(const session::Session& session);

// The head pose and room of the frame: the layout's start without --pose;
// with --pose, --room or else the one room whose box or prism holds the
// head; with --path, line K's after walking lines 0..K (walk/replay.hpp),
// at time K / fps, and `session` becomes the one with the pairing in force at
// line K (layout-format.md, "Changes while walking"). Throws InputError for a
// bad path file, UsageError for a K past its last line.
render::FrameDesc frame_for(session::Session& session, const ViewOptions& options);

// With --path FILE --frame K (K > 0): the session with the pairing frame K
// started with, the one `walk`'s seen test reads at line K (after the
// changes made at lines 0..K-1, walked with the same view options); it
// differs from frame_for's only where a change is made at line K.
// `session` itself without --path or for K = 0. `session` is the loaded
// one (before frame_for replaces it). Throws as frame_for does.
session::Session session_frame_started_with(const session::Session& session, const ViewOptions& options);

// The same frame for the reference tracer (threads: 0 = all cores).
trace::TraceDesc trace_desc_for(const render::FrameDesc& frame, int threads = 0);

// The outputs (--out, --ids) and the layout, declared before any work: a
// UsageError when two of them are the same file.
CommandOutputs frame_outputs(const ViewOptions& options);

// Writes the colour image and, with --ids, the id map, both or neither;
// throws InputError naming the file that could not be written.
void write_frame_pngs(CommandOutputs& outputs, const ViewOptions& options, int width, int height,
                      const std::vector<std::uint8_t>& rgb, const std::vector<std::uint8_t>& ids);

}  // namespace impossible::cli
