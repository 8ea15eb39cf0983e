// Options of `impossible preview` (docs/preview.md), parsed into plain data.
#pragma once

#include <optional>
#include <string>

#include "cli/args.hpp"
#include "cli/technique_options.hpp"
#include "render/frame.hpp"

namespace impossible::preview {

// How the two eyes reach the window.
enum class PreviewView {
    Parallel,  // left eye in the left half (parallel viewing)
    Cross,     // halves swapped, for cross-eyed viewing
    Anaglyph,  // one picture: red = left eye, cyan = right eye
};

const char* view_name(PreviewView view);
PreviewView next_view(PreviewView view);

// The renderer's defaults with eyes of 640 × 480.
render::FrameDesc default_preview_frame();

struct PreviewOptions {
    std::optional<std::string> layout_path;  // none: the built-in default (no reload)
    // Every frame setting (eye size, ipd, fov, max_depth, stereo, clip,
    // cull_portals); the head, the room and, in the window, the eye size are
    // set each frame.
    render::FrameDesc frame = default_preview_frame();
    PreviewView view = PreviewView::Parallel;
    std::optional<std::string> path_file;    // --path: physical poses, one a frame
    std::optional<double> fps;               // --fps: frame k of --path is at time k / fps
    std::optional<std::string> screenshots;  // --screenshots DIR: every frame saved
    std::optional<long> frames;              // --frames N: quit after N frames
    // --technique and --texture-from-level as given (cli/technique_options.hpp),
    // put into frame with --portal-texture by parse_preview_options.
    std::optional<cli::Technique> technique;
    std::optional<int> texture_from_level;
    bool hud = true;
    bool minimap = true;
    bool vsync = true;
    bool hand = false;               // G: a hand held out in front of the head (preview/head.hpp)
    double hand_distance = 0.4;      // , and . : how far in front, metres
    bool shadow_options = false;     // --shadow-size or --no-shadows given (frame has their values)
    std::optional<std::string> hmd;  // --hmd FILE.json (its optics are in frame)
};

// Throws UsageError (exit 2) for unknown or conflicting options and
// InputError (exit 1) for bad values.
PreviewOptions parse_preview_options(const std::vector<std::string>& args, bool* help);

std::string preview_help();

}  // namespace impossible::preview
