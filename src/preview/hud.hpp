// The preview's HUD: a few lines of text (stb_easy_font from Debian's
// libstb-dev) on a dark panel at the window's top left, and the layout's
// errors after a failed reload.
#pragma once

#include <deque>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "preview/overlay.hpp"

namespace impossible::preview {

// Median of the last frame times (ms); 0 for none.
double median_ms(const std::deque<double>& frame_ms);

// Appends `text` (one line, ASCII) at pixel (x, y), top left, `scale` times
// stb_easy_font's size (about 6 × 12 pixels a character at scale 1). Returns
// the text's width in pixels.
float add_text(OverlayBatch& batch, float x, float y, const std::string& text, glm::vec4 color, float scale);

struct HudText {
    std::vector<std::string> lines;   // white
    std::vector<std::string> errors;  // red, after the lines
};

// The panel with the lines, top left; returns its height in pixels.
float add_hud(OverlayBatch& batch, const HudText& hud, float scale);

}  // namespace impossible::preview
