// A line of text as filled rectangles, for pictures drawn without a font
// renderer (the PNG of `impossible plan`): stb_easy_font's segment font
// (Sean Barrett, public domain; Debian's libstb), printable ASCII only
// (anything else is drawn as '?'). In font units: a capital is 7 units high
// above the baseline at y = 7 (y grows down), descenders reach y = 9, and
// a character advances about 6 units.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

namespace impossible::image {

struct TextRect {
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // font units, from the line's top left
};

inline constexpr float kTextBaseline = 7.0f;       // font units below the line's top
inline constexpr std::size_t kMaxTextChars = 400;  // longer text is cut

std::vector<TextRect> text_rects(std::string_view text);
float text_width(std::string_view text);  // font units

}  // namespace impossible::image
