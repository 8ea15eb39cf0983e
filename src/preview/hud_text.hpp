// The words of the preview's HUD: what the frame shows and how it was drawn,
// the keys, and the errors of a failed reload. Plain strings, no GL.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "changes/change_walk.hpp"
#include "layout/layout.hpp"
#include "math/pose.hpp"
#include "preview/hud.hpp"
#include "preview/options.hpp"
#include "render/frame.hpp"

namespace impossible::preview {

// What the HUD reports of one frame besides the options.
struct HudFacts {
    std::string title;
    double median_ms = 0.0;             // of the last timed frames
    std::size_t timed_frames = 0;       // how many
    int eye_width = 0, eye_height = 0;  // as drawn this frame
    std::string room;                   // the room's id
    int portal_passes_drawn = 0, portal_passes_culled = 0, max_level_reached = 0;
    math::HeadPose physical;
    bool cursor_captured = false;
    double time = 0.0;  // seconds, the frame's time for moving props
    // Lit layouts ("lighting": "lights"): the lights of the head's room, the
    // light images of the cells drawn (render::FrameStats::light_images) and
    // the light depth in use; lit false: no lights line.
    bool lit = false;
    int room_lights = 0;
    int light_images = 0;
    int light_depth = 0;
    double exposure = 0.0;  // EV, the frame's (--exposure, the keys 9 and 0, or the layout's)
    std::string changes;    // changes_line; empty: the layout has none (no line)
};

// The HUD's line on a layout's changes (layout-format.md, "Changes while
// walking"): those armed and waiting for their doors to be out of sight,
// those made (with the walk's frame), how many are not armed yet, and the
// portal passes of the frame's seen test (session::WalkDriver::seen_passes;
// none when it did not run: no armed change waited).
std::string changes_line(const layout::Layout& layout, const changes::ChangeWalk& walk, int seen_passes);

inline constexpr std::size_t kMaxReloadErrors = 8;

// The HUD's lines (none with options.hud off) and, after a failed reload, its
// first errors in red.
HudText hud_text(const PreviewOptions& options, const HudFacts& facts, const std::vector<std::string>& reload_errors);

// The red lines for the errors of a failed reload (none without errors).
std::vector<std::string> reload_error_lines(const std::vector<std::string>& errors);

// The HUD's text scale in a window fb_h pixels high: 1 below 400, 1.5
// below 800, else 2.
float hud_scale(int fb_h);

// `hud` cut to fit a window of fb_w × fb_h pixels at `scale` (about 6 × 12
// pixels a character at scale 1), so that a small window (--size 160x90)
// keeps most of its view: at most 40 % of the height in rows (at least one;
// the errors of a failed reload first, then the first status lines) and its
// width in characters, a longer line ending in "...". A window of the default
// size (640x480 an eye, 1280x480) keeps every line whole.
HudText fit_hud(HudText hud, int fb_w, int fb_h, float scale);

// printf's %.*f.
std::string fixed(double value, int decimals);

}  // namespace impossible::preview
