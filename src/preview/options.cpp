#include "preview/options.hpp"
#include "cli/view_options.hpp"

#include <tuple>

namespace impossible::preview {

using cli::InputError;
using cli::ParsedArgs;
using cli::UsageError;
using cli::parse_args;
using cli::parse_clip;
using cli::parse_fov;
using cli::parse_int;
using cli::parse_ipd;
using cli::parse_size;
using cli::parse_samples;
using cli::parse_stereo;

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

const char* preview_help() {
    return "usage: impossible preview [LAYOUT] [options]\n"
           "A window showing the side-by-side stereo view of a layout (the built-in default without\n"
           "LAYOUT), drawn by the same renderer as 'render'. Walk it as in a headset: the keys move the\n"
           "physical head inside the play area and portals teleport as in 'walk'. The layout file is\n"
           "reloaded when it changes; an invalid edit shows its errors and keeps the last good layout.\n\n"
           "  --size WxH              size of each eye's image (default 640x480); the window starts 2W x H\n"
           "                          and keeps the eye aspect when resized\n"
           "  --cross                 swap the halves for cross-eyed viewing\n"
           "  --anaglyph              one red-cyan picture (red: left eye)\n"
           "  --ipd M                 distance between the eyes (default 0.064)\n"
           "  --fov DEG               vertical field of view of each eye (default 90)\n"
           "  --max-depth N           portals one line of sight may pass (default 8, at most 250)\n"
           "  --stereo MODE           clip-shift (default), viewport-index or two-pass\n"
           "  --clip MODE             clip-distance (default) or oblique\n"
           "  --no-cull               draw every portal and prop without per-eye culling and scissor\n"
           "  --samples N             multisampling: 1 (default), 2, 4, 8 or 16 samples per pixel (the\n"
           "                          counts the driver offers; llvmpipe: 4)\n"
           "  --no-hud, --no-minimap  start with the HUD / minimap hidden\n"
           "  --no-vsync              do not wait for the display between frames\n"
           "Scripted mode (tests, demos):\n"
           "  --path FILE             replay physical head poses, one a frame (the format of 'walk');\n"
           "                          afterwards the head stays at the last pose under keyboard control\n"
           "  --screenshots DIR       save every frame: frame-NNNN.png (the renderer's side-by-side\n"
           "                          image, exactly as 'render' writes it at --size), frame-NNNN-ids.png,\n"
           "                          window-NNNN.png (the window with HUD and minimap) and frames.jsonl\n"
           "                          (the virtual pose and room of each frame)\n"
           "  --frames N              quit after N frames\n"
           "Keys: mouse look (click captures the cursor, Esc releases it, Esc again quits);\n"
           "  W A S D / arrows move, Q / E down / up, Shift faster, R back to the start;\n"
           "  H HUD, M minimap, V parallel / cross / anaglyph, [ ] recursion depth, - = IPD,\n"
           "  C clip mode, X portal culling, P or F12 saves the window (screenshot-NNNN.png in the\n"
           "  --screenshots DIR, or the current directory)\n";
}

PreviewOptions parse_preview_options(const std::vector<std::string>& args, bool* help) {
    const ParsedArgs a = parse_args(
        args, {"--size", "--ipd", "--fov", "--max-depth", "--stereo", "--clip", "--samples", "--path", "--screenshots",
               "--frames"},
        {"--cross", "--anaglyph", "--no-cull", "--no-hud", "--no-minimap", "--no-vsync"}, 1);
    PreviewOptions o;
    *help = a.help;
    if (a.help) return o;
    if (!a.positional.empty()) o.layout_path = a.positional[0];
    if (a.flag("--cross") && a.flag("--anaglyph")) throw UsageError("--cross and --anaglyph exclude each other");
    if (a.flag("--cross")) o.view = PreviewView::Cross;
    if (a.flag("--anaglyph")) o.view = PreviewView::Anaglyph;
    if (auto v = a.value("--size")) {
        std::tie(o.frame.eye_width, o.frame.eye_height) = parse_size("--size", *v);
        if (o.frame.eye_width > 4096 || o.frame.eye_height > 4096)
            throw InputError("--size: " + *v + " is larger than a window can be (at most 4096x4096 per eye)");
    }
    if (auto v = a.value("--ipd")) o.frame.ipd = parse_ipd(*v);
    if (auto v = a.value("--fov")) o.frame.fov_y_deg = parse_fov(*v);
    if (auto v = a.value("--max-depth")) o.frame.max_depth = parse_int("--max-depth", *v, 0, 250);
    if (auto v = a.value("--stereo")) o.frame.stereo = parse_stereo(*v);
    if (auto v = a.value("--clip")) o.frame.clip = parse_clip(*v);
    if (auto v = a.value("--samples")) o.frame.samples = parse_samples(*v);
    o.frame.cull_portals = !a.flag("--no-cull");
    o.hud = !a.flag("--no-hud");
    o.minimap = !a.flag("--no-minimap");
    o.vsync = !a.flag("--no-vsync");
    o.path_file = a.value("--path");
    o.screenshots = a.value("--screenshots");
    if (auto v = a.value("--frames")) o.frames = parse_int("--frames", *v, 1, 100000000);
    return o;
}

}  // namespace impossible::preview
