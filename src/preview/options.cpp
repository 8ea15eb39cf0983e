#include "preview/options.hpp"

#include <tuple>

#include "cli/option_table.hpp"
#include "cli/view_options.hpp"

namespace impossible::preview {

using cli::apply_options;
using cli::InputError;
using cli::Option;
using cli::options_help;
using cli::OptionValue;
using cli::parse_args;
using cli::parse_clip;
using cli::parse_fov;
using cli::parse_fps;
using cli::parse_int;
using cli::parse_ipd;
using cli::parse_light_depth;
using cli::parse_samples;
using cli::parse_shadow_size;
using cli::parse_size;
using cli::parse_stereo;
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
    if (size.first > 4096 || size.second > 4096)
        throw InputError(v.name + ": " + v.text + " is larger than a window can be (at most 4096x4096 per eye)");
    return size;
}

constexpr std::size_t kPreviewHelpColumn = 26;
// In the order of the help and of the checks.
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
    {"--ipd", "M", "distance between the eyes (default 0.064)",
     [](PreviewOptions& o, const OptionValue& v) { o.frame.ipd = parse_ipd(v.text); }},
    {"--fov", "DEG", "vertical field of view of each eye (default 90)",
     [](PreviewOptions& o, const OptionValue& v) { o.frame.fov_y_deg = parse_fov(v.text); }},
    {"--fov-angles", "L,R,U,D", "asymmetric field of view as 'render' (4 or 8 numbers, degrees)",
     [](PreviewOptions& o, const OptionValue& v) { o.frame.eye_optics = cli::parse_fov_angles(v.text); }},
    {"--hmd", "FILE.json", "a headset profile as 'render' (docs/headsets.md)",
     [](PreviewOptions& o, const OptionValue& v) { o.hmd = v.text; }},
    {"--max-depth", "N", "portals one line of sight may pass (default 8, at most 250)",
     [](PreviewOptions& o, const OptionValue& v) { o.frame.max_depth = parse_int(v.name, v.text, 0, 250); }},
    {"--stereo", "MODE", "clip-shift (default), viewport-index or two-pass",
     [](PreviewOptions& o, const OptionValue& v) { o.frame.stereo = parse_stereo(v.text); }},
    {"--clip", "MODE", "clip-distance (default) or oblique",
     [](PreviewOptions& o, const OptionValue& v) { o.frame.clip = parse_clip(v.text); }},
    {"--no-cull", nullptr, "draw every portal and prop without per-eye culling and scissor",
     [](PreviewOptions& o, const OptionValue&) { o.frame.cull_portals = false; }},
    {"--portal-texture", "SCALE", "hybrid: the textures' scale of the eye size, as 'render'",
     [](PreviewOptions& o, const OptionValue& v) {
         o.frame.portal_texture_scale = cli::parse_portal_texture(v.name, v.text);
     }},
    {"--technique", "NAME", "stencil (default), hybrid or z-clear, as 'render'",
     [](PreviewOptions& o, const OptionValue& v) { o.technique = cli::parse_technique(v.name, v.text); }},
    {"--texture-from-level", "K", "hybrid: the level whose doors take textures (default 0)",
     [](PreviewOptions& o, const OptionValue& v) { o.texture_from_level = parse_int(v.name, v.text, 0, 250); }},
    {"--samples", "N",
     "multisampling: 1 (default), 2, 4, 8 or 16 samples per pixel (the\n"
     "counts the driver offers; llvmpipe: 4)",
     [](PreviewOptions& o, const OptionValue& v) { o.frame.samples = parse_samples(v.text); }},
    {"--light-depth", "N",
     "portals light may pass (0..16), instead of the layout's\n"
     "light_depth; only with \"lighting\": \"lights\"",
     [](PreviewOptions& o, const OptionValue& v) { o.frame.light_depth = parse_light_depth(v.text); }},
    {"--shadow-size", "N",
     "texels per face side of the props' cube shadow maps (default\n"
     "512, at most 4096; 0: props cast no shadows)",
     [](PreviewOptions& o, const OptionValue& v) {
         o.frame.shadow_map_size = parse_shadow_size(v.text);
         o.shadow_options = true;
     }},
    {"--no-shadows", nullptr, "props cast no shadows (lit layouts)",
     [](PreviewOptions& o, const OptionValue&) {
         o.frame.shadows = false;
         o.shadow_options = true;
     }},
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
     [](PreviewOptions& o, const OptionValue& v) { o.fps = parse_fps(v.text); }},
    {"--screenshots", "DIR",
     "save every frame: frame-NNNN.png (the renderer's side-by-side\n"
     "image, exactly as 'render' writes it at --size), frame-NNNN-ids.png,\n"
     "window-NNNN.png (the window with HUD and minimap) and frames.jsonl\n"
     "(the virtual pose and room of each frame)",
     [](PreviewOptions& o, const OptionValue& v) { o.screenshots = v.text; }},
    {"--frames", "N", "quit after N frames",
     [](PreviewOptions& o, const OptionValue& v) { o.frames = parse_int(v.name, v.text, 1, 100000000); }},
};

}  // namespace

std::string preview_help() { return kPreviewUsage + options_help(kPreviewOptions, kPreviewHelpColumn) + kPreviewKeys; }

PreviewOptions parse_preview_options(const std::vector<std::string>& args, bool* help) {
    const ParsedArgs a = parse_args(args, 1, kPreviewOptions);
    PreviewOptions o;
    *help = a.help;
    if (a.help) return o;
    if (!a.positional.empty()) o.layout_path = a.positional[0];
    if (a.flag("--cross") && a.flag("--anaglyph")) throw UsageError("--cross and --anaglyph exclude each other");
    if (a.value("--fps") && !a.value("--path")) throw UsageError("--fps needs --path FILE");
    cli::check_headset_combinations(a);
    apply_options(kPreviewOptions, a, o);
    cli::resolve_technique(o.technique, o.texture_from_level, o.frame);
    if (o.hmd) cli::apply_hmd_profile(*o.hmd, o.frame, a.value("--size").has_value(), a.value("--ipd").has_value());
    if (o.frame.eye_width > 4096 || o.frame.eye_height > 4096)
        throw InputError("--hmd: " + *o.hmd +
                         "'s eye size is larger than a window can be (at most 4096x4096 per eye; give --size)");
    return o;
}

}  // namespace impossible::preview
