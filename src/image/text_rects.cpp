// The segment font as rectangles; see text_rects.hpp.
#include "image/text_rects.hpp"

#include <algorithm>
#include <string>

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wuseless-cast"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#endif
#include <stb_easy_font.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace impossible::image {
namespace {

struct EasyFontVertex {  // the layout stb_easy_font writes
    float x, y, z;
    unsigned char color[4];
};

std::string printable(std::string_view text) {
    std::string line(text.substr(0, kMaxTextChars));
    for (char& c : line)
        if (c < 32 || c > 126) c = '?';
    return line;
}

}  // namespace

std::vector<TextRect> text_rects(std::string_view text) {
    std::string line = printable(text);
    // At most ~60 quads a character (the font's segments); 4 vertices a quad.
    std::vector<EasyFontVertex> quads(line.size() * 64 * 4 + 4);
    const int count = stb_easy_font_print(0.0f, 0.0f, line.data(), nullptr, quads.data(),
                                          static_cast<int>(quads.size() * sizeof(EasyFontVertex)));
    std::vector<TextRect> out;
    out.reserve(static_cast<std::size_t>(count));
    for (int q = 0; q < count; ++q) {
        const EasyFontVertex* v = &quads[static_cast<std::size_t>(q) * 4];
        TextRect r{v[0].x, v[0].y, v[0].x, v[0].y};
        for (int k = 1; k < 4; ++k) {
            r.x0 = std::min(r.x0, v[k].x), r.y0 = std::min(r.y0, v[k].y);
            r.x1 = std::max(r.x1, v[k].x), r.y1 = std::max(r.y1, v[k].y);
        }
        out.push_back(r);
    }
    return out;
}

float text_width(std::string_view text) {
    std::string line = printable(text);
    return static_cast<float>(stb_easy_font_width(line.data()));
}

}  // namespace impossible::image
