#include "cli/view_options.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <tuple>

#include "base/text.hpp"
#include "cli/field_flags.hpp"
#include "image/png.hpp"
#include "layout/hmd_profile.hpp"
#include "layout/path_file.hpp"
#include "lights/light_bound.hpp"
#include "lights/light_images.hpp"
#include "math/view_limits.hpp"
#include "session/view_request.hpp"
#include "session/walk_driver.hpp"

namespace impossible::cli {

namespace lim = math::limits;

namespace {

gl::Backend parse_backend(const OptionValue& v) {
    if (const std::optional<gl::Backend> backend = gl::parse_backend(v.text)) return *backend;
    throw InputError(v.name + ": '" + v.text + "' is not egl or osmesa");
}

// The command's own rows, in the order of the help and of the checks (the
// first bad value in this order is the one reported); the frame's rows
// (cli/frame_options.hpp) follow them.
constexpr Option<ViewOptions> kViewOptions[] = {
    {"--pose", "X,Y,Z,YAW,PITCH,ROLL", "head centre and orientation (degrees); default: the layout's start",
     [](ViewOptions& o, const OptionValue& v) { o.pose = parse_pose(v); }},
    {"--room", "ID",
     "the room the head is in; default: start.room, or with --pose the\n"
     "one room whose box or prism holds the head",
     [](ViewOptions& o, const OptionValue& v) { o.room = v.text; }},
    {"--path", "FILE",
     "instead of --pose, --room, --time and --hands: line K of a walk\n"
     "(the `walk` path format, 6 or 18 numbers a line) after walking\n"
     "lines 0..K, with its hands, at time K / fps; needs --frame K",
     [](ViewOptions& o, const OptionValue& v) { o.path = v.text; }},
    {"--frame", "K", "the line of --path, from 0",
     [](ViewOptions& o, const OptionValue& v) {
         o.path_frame = parse_int(v.name, v.text, lim::kPathFrame.min, lim::kPathFrame.max);
     }},
    {"--fps", "N", "frames a second of --path: line K is at time K / N (default 90)",
     [](ViewOptions& o, const OptionValue& v) { o.fps = parse_fps(v); }},
    {"--out", "FILE.png", "side-by-side colour image (default stereo.png)",
     [](ViewOptions& o, const OptionValue& v) { o.out = v.text; }},
    {"--ids", "FILE.png", "cell-id map: 1 + room index, 0 nothing, 255 recursion limit",
     [](ViewOptions& o, const OptionValue& v) { o.ids = v.text; }},
    {"--backend", "egl|osmesa", "headless OpenGL context (default egl, falling back to osmesa)",
     [](ViewOptions& o, const OptionValue& v) { o.backend = parse_backend(v); }},
    {"--stats", nullptr, "print draw calls, triangles and portal passes to stderr",
     [](ViewOptions& o, const OptionValue&) { o.stats = true; }},
};

// The frame's rows in help order: the view's, the technique's, the diagnostics'.
std::vector<Option<FrameOptions>> all_frame_rows() {
    std::vector<Option<FrameOptions>> rows;
    for (OptionTable<FrameOptions> t : {view_rows(), technique_rows(), diagnostic_rows()})
        rows.insert(rows.end(), t.begin(), t.end());
    return rows;
}

}  // namespace

ViewTables view_options() {
    static const std::vector<Option<FrameOptions>> frame = all_frame_rows();
    return {kViewOptions, frame};
}

ViewTables trace_view_options() {
    static const std::vector<Option<FrameOptions>> frame =
        without(view_options().frame, {"--shadow-size", "--no-shadows"});
    return {kViewOptions, frame};
}

std::string view_help(const ViewTables& tables) {
    return options_help(tables.own, kViewHelpColumn) + options_help(tables.frame, kViewHelpColumn);
}

std::string model_warnings_text(const session::Session& session) {
    std::string out;
    for (const std::string& w : session.layout().model_warnings) out += "warning: " + w + "\n";
    return out;
}

std::string light_options_warning(const session::Session& session, const std::optional<int>& light_depth,
                                  bool shadow_options) {
    const layout::Layout& layout = session.layout();
    if (layout.lighting == layout::Lighting::Lights) {
        // The light work's bound (docs/bounded-work.md): both renderers light
        // at most lights::kMaxLightPaths paths with lights::kMaxLightRects
        // path rectangles, at a lower depth, or with fewer lights, if need be.
        const int asked = light_depth.value_or(layout.light_depth);
        const lights::LightBound bound = session.light_bound();
        const lights::LightCut cut = lights::light_cut(bound, asked);
        if (cut == lights::LightCut::None) return "";
        const std::string what = cut == lights::LightCut::Paths
                                     ? std::to_string(lights::kMaxLightPaths) + " light paths"
                                     : std::to_string(lights::kMaxLightRects) + " path rectangles";
        std::string lit = "lit at light depth " + std::to_string(std::min(asked, bound.depth));
        if (bound.lit_lights < bound.lights)
            lit += " by " + std::to_string(bound.lit_lights) + " of its " + std::to_string(bound.lights) + " lights";
        return "warning: light depth " + std::to_string(asked) + " gives more than " + what + " in " +
               one_line(layout.source, 1000) + ": " + lit + "\n";
    }
    if (!light_depth && !shadow_options) return "";
    const std::string what = light_depth && shadow_options ? "--light-depth and the shadow options have"
                             : light_depth                 ? "--light-depth has"
                                                           : "the shadow options have";
    return "warning: " + what + " no effect: " + one_line(layout.source, 1000) + "'s lighting is \"fixed\"\n";
}

namespace {

bool has_option(OptionTable<ViewOptions> table, std::string_view name) {
    for (const Option<ViewOptions>& o : table)
        if (name == o.name) return true;
    return false;
}

// The usage errors of --path, --frame and --fps, before any value is read.
void check_path_combinations(const ParsedArgs& args) {
    if (args.value("--path")) {
        for (const char* other : {"--pose", "--room", "--time", "--hands"})
            if (args.value(other))
                throw UsageError(std::string("--path and ") + other +
                                 " exclude each other (line K of the path gives the head, its room, the hands and "
                                 "the time)");
        if (!args.value("--frame")) throw UsageError("--path needs --frame K, the line to draw (from 0)");
        return;
    }
    for (const char* needs_path : {"--frame", "--fps"})
        if (args.value(needs_path)) throw UsageError(std::string(needs_path) + " needs --path FILE");
}

}  // namespace

ViewOptions parse_view_options(const ParsedArgs& args, const ViewTables& tables) {
    if (has_option(tables.own, "--path")) check_path_combinations(args);
    check_headset_combinations(args);
    ViewOptions o;
    if (!args.positional.empty()) o.layout_path = args.positional[0];
    apply_options(tables.own, args, o);
    apply_options(tables.frame, args, o);
    finish_frame_options(args, o);
    return o;
}

trace::TraceDesc trace_desc_for(const render::FrameDesc& frame, int threads) {
    trace::TraceDesc desc;
    static_cast<math::View&>(desc) = frame;
    desc.threads = threads;
    desc.samples = frame.samples;
    return desc;
}

CommandOutputs frame_outputs(const ViewOptions& options) {
    CommandOutputs outputs;
    if (options.layout_path) outputs.input("the layout", *options.layout_path);
    if (options.path) outputs.input("--path", *options.path);
    if (options.hmd) outputs.input("--hmd", *options.hmd);
    outputs.output("--out", options.out);
    if (options.ids) outputs.output("--ids", *options.ids);
    return outputs;
}

void write_frame_pngs(CommandOutputs& outputs, const ViewOptions& options, int width, int height,
                      const std::vector<std::uint8_t>& rgb, const std::vector<std::uint8_t>& ids) {
    auto encode = [&](const std::string& path, int channels, const std::vector<std::uint8_t>& pixels) {
        outputs.set(path, value_or_throw(image::encode_png(width, height, channels, pixels), path));
    };
    encode(options.out, 3, rgb);
    if (options.ids) encode(*options.ids, 1, ids);
    outputs.commit();
}

namespace {

// --path FILE --frame K [--fps N]: line K of the walk; the session with
// the pairing in force there.
session::Session set_path_frame(render::FrameDesc& f, const session::Session& session, const ViewOptions& o) {
    const std::vector<layout::PathFrame> frames = value_or_throw(layout::read_path_frames_file(*o.path));
    const std::size_t k = static_cast<std::size_t>(o.path_frame.value_or(0));
    if (k >= frames.size())
        throw UsageError(
            "--frame " + std::to_string(k) + ": " + *o.path + " holds " + std::to_string(frames.size()) +
            (frames.size() == 1 ? " pose (frame 0)" : " poses (frames 0.." + std::to_string(frames.size() - 1) + ")"));
    return session::replay_to(session, f, frames, k, o.fps.value_or(layout::kDefaultPathFps));
}

}  // namespace

session::Session session_frame_started_with(const session::Session& session, const ViewOptions& o) {
    if (!o.path || o.path_frame.value_or(0) == 0) return session;
    ViewOptions before = o;
    before.path_frame = *o.path_frame - 1;
    render::FrameDesc f = o.frame;
    return set_path_frame(f, session, before);
}

render::FrameDesc frame_for(session::Session& session, const ViewOptions& o) {
    render::FrameDesc f = o.frame;
    if (o.path) {
        session = set_path_frame(f, session, o);
        return f;
    }
    // The one rule of the head's room (session/view_request.hpp).
    if (const std::optional<session::FieldError> problem = session::place_head(session.layout(), {o.pose, o.room}, f))
        throw InputError(flag_message(*problem));
    return f;
}

}  // namespace impossible::cli
