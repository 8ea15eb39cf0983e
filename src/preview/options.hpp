// Options of `impossible preview` (docs/preview.md), parsed into plain data.
#pragma once

#include <optional>
#include <string>

#include "cli/args.hpp"
#include "cli/frame_options.hpp"
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

// The frame's settings (FrameOptions: eye size, ipd, fov, max_depth, stereo,
// clip, culling...; the head, the room and, in the window, the eye size are
// set each frame) and the preview's own.
struct PreviewOptions : cli::FrameOptions {
    PreviewOptions() { frame = default_preview_frame(); }
    std::optional<std::string> layout_path;  // none: the built-in default (no reload)
    PreviewView view = PreviewView::Parallel;
    std::optional<std::string> path_file;    // --path: physical poses, one a frame
    std::optional<double> fps;               // --fps: frame k of --path is at time k / fps
    std::optional<std::string> screenshots;  // --screenshots DIR: every frame saved
    std::optional<long> frames;              // --frames N: quit after N frames
    bool hud = true;
    bool minimap = true;
    bool vsync = true;
    bool hand = false;           // G: a hand held out in front of the head (preview/head.hpp)
    double hand_distance = 0.4;  // , and . : how far in front, metres
};

// Throws UsageError (exit 2) for unknown or conflicting options and
// InputError (exit 1) for bad values.
PreviewOptions parse_preview_options(const std::vector<std::string>& args, bool* help);

std::string preview_help();

}  // namespace impossible::preview
