#include "preview/options.hpp"

#include <tuple>

#include "cli/option_table.hpp"
#include "cli/view_options.hpp"
#include "math/view_limits.hpp"

namespace impossible::preview {

using cli::apply_options;
using cli::FrameOptions;
using cli::InputError;
using cli::Option;
using cli::options_help;
using cli::OptionTable;
using cli::OptionValue;
using cli::parse_args;
using cli::parse_int;
using cli::parse_size;
using cli::ParsedArgs;
using cli::UsageError;

const char* view_name(PreviewView view) {
    switch (view) {
        case PreviewView::Parallel: return "parallel";
        case PreviewView::Cross: return "cross";
        case PreviewView::Anaglyph: return "anaglyph";
    }
    return "?";
}

PreviewView next_view(PreviewView view) {
    switch (view) {
        case PreviewView::Parallel: return PreviewView::Cross;
        case PreviewView::Cross: return PreviewView::Anaglyph;
        case PreviewView::Anaglyph: return PreviewView::Parallel;
    }
    return PreviewView::Parallel;
}

render::FrameDesc default_preview_frame() {
    render::FrameDesc f;
    f.eye_width = 640;
    f.eye_height = 480;
    return f;
}

namespace {

const char* kPreviewUsage =
    "usage: impossible preview [LAYOUT] [options]\n"
    "A window showing the side-by-side stereo view of a layout (the built-in default without\n"
    "LAYOUT), drawn by the same renderer as 'render'. Walk it as in a headset: the keys move the\n"
    "physical head inside the play area and portals teleport as in 'walk'. The layout file is\n"
    "reloaded when it changes; an invalid edit shows its errors and keeps the last good layout.\n\n";

const char* kPreviewKeys =
    "Keys: mouse look (click captures the cursor, Esc releases it, Esc again quits);\n"
    "  W A S D / arrows move, Q / E down / up, Shift faster, R back to the start;\n"
    "  H HUD, M minimap, V parallel / cross / anaglyph, [ ] recursion depth, - = IPD,\n"
    "  G a hand held in front of the head (the right hand; the left hangs at your side),\n"
    "  , . pull it closer / push it further (0.1..1 m; walk to push it through a door),\n"
    "  C clip mode, X portal culling, P or F12 saves the window (screenshot-NNNN.png in the\n"
    "  --screenshots DIR, or the current directory)\n";

std::pair<int, int> parse_window_size(const OptionValue& v) {
    const std::pair<int, int> size = parse_size(v.name, v.text);
    if (!math::limits::kWindowEyeSide.contains(size.first) || !math::limits::kWindowEyeSide.contains(size.second))
        throw InputError(v.name + ": " + v.text + " is larger than a window can be (at most 4096x4096 per eye)");
    return size;
}

constexpr std::size_t kPreviewHelpColumn = 26;
// The preview's own rows, in the order of the help and of the checks; the
// frame's rows (cli/frame_options.hpp) but --size, --time and --hands follow.
constexpr Option<PreviewOptions> kPreviewOptions[] = {
    {"--size", "WxH",
     "size of each eye's image (default 640x480); the window starts 2W x H\n"
     "and keeps the eye aspect when resized",
     [](PreviewOptions& o, const OptionValue& v) {
         std::tie(o.frame.eye_width, o.frame.eye_height) = parse_window_size(v);
     }},
    {"--cross", nullptr, "swap the halves for cross-eyed viewing",
     [](PreviewOptions& o, const OptionValue&) { o.view = PreviewView::Cross; }},
    {"--anaglyph", nullptr, "one red-cyan picture (red: left eye)",
     [](PreviewOptions& o, const OptionValue&) { o.view = PreviewView::Anaglyph; }},
    {"--no-hud", nullptr, "start with the HUD / minimap hidden",
     [](PreviewOptions& o, const OptionValue&) { o.hud = false; }, "--no-hud, --no-minimap"},
    {"--no-minimap", nullptr, nullptr, [](PreviewOptions& o, const OptionValue&) { o.minimap = false; }},
    {"--no-vsync", nullptr, "do not wait for the display between frames",
     [](PreviewOptions& o, const OptionValue&) { o.vsync = false; }},
    {"--path", "FILE",
     "replay physical head poses, one a frame (the format of 'walk'; a\n"
     "line of 18 numbers also places the hands); afterwards the head\n"
     "stays at the last pose under keyboard control",
     [](PreviewOptions& o, const OptionValue& v) { o.path_file = v.text; }, nullptr, "Scripted mode (tests, demos):"},
    {"--fps", "N",
     "with --path: frame k is at time k / N for moving props (default\n"
     "90); without it, the time is the seconds since the preview started",
     [](PreviewOptions& o, const OptionValue& v) { o.fps = cli::parse_fps(v); }},
    {"--screenshots", "DIR",
     "save every frame: frame-NNNN.png (the renderer's side-by-side\n"
     "image, exactly as 'render' writes it at --size), frame-NNNN-ids.png,\n"
     "window-NNNN.png (the window with HUD and minimap) and frames.jsonl\n"
     "(the virtual pose and room of each frame)",
     [](PreviewOptions& o, const OptionValue& v) { o.screenshots = v.text; }},
    {"--frames", "N", "quit after N frames",
     [](PreviewOptions& o, const OptionValue& v) { o.frames = parse_int(v.name, v.text, 1, 100000000); }},
};

// render's frame rows, but the window's --size and what the preview drives
// itself (the time, and the hands by G).
OptionTable<FrameOptions> preview_frame_rows() {
    static const std::vector<Option<FrameOptions>> rows = [] {
        std::vector<Option<FrameOptions>> all;
        for (OptionTable<FrameOptions> t : {cli::view_rows(), cli::technique_rows(), cli::diagnostic_rows()})
            all.insert(all.end(), t.begin(), t.end());
        return cli::without(all, {"--size", "--time", "--hands"});
    }();
    return rows;
}

}  // namespace

std::string preview_help() {
    return kPreviewUsage + options_help(kPreviewOptions, kPreviewHelpColumn) +
           options_help(preview_frame_rows(), kPreviewHelpColumn) + kPreviewKeys;
}

PreviewOptions parse_preview_options(const std::vector<std::string>& args, bool* help) {
    const ParsedArgs a = parse_args(args, 1, kPreviewOptions, preview_frame_rows());
    PreviewOptions o;
    *help = a.help;
    if (a.help) return o;
    if (!a.positional.empty()) o.layout_path = a.positional[0];
    if (a.flag("--cross") && a.flag("--anaglyph")) throw UsageError("--cross and --anaglyph exclude each other");
    if (a.value("--fps") && !a.value("--path")) throw UsageError("--fps needs --path FILE");
    cli::check_headset_combinations(a);
    apply_options(kPreviewOptions, a, o);
    apply_options(preview_frame_rows(), a, o);
    cli::finish_frame_options(a, o);
    if (!math::limits::kWindowEyeSide.contains(o.frame.eye_width) ||
        !math::limits::kWindowEyeSide.contains(o.frame.eye_height))
        throw InputError("--hmd: " + *o.hmd +
                         "'s eye size is larger than a window can be (at most 4096x4096 per eye; give --size)");
    return o;
}

}  // namespace impossible::preview
