#include "preview/hud.hpp"

#include <algorithm>
#include <vector>

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#endif
#include <stb_easy_font.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace impossible::preview {
namespace {

constexpr float kLineHeight = 12.0f;  // stb_easy_font's line advance at scale 1
constexpr std::size_t kMaxChars = 200;

struct EasyFontVertex {  // the layout stb_easy_font writes
    float x, y, z;
    unsigned char color[4];
};

}  // namespace

double median_ms(const std::deque<double>& frame_ms) {
    if (frame_ms.empty()) return 0.0;
    std::vector<double> v(frame_ms.begin(), frame_ms.end());
    const std::size_t mid = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid), v.end());
    if (v.size() % 2) return v[mid];
    const double upper = v[mid];
    const double lower = *std::max_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid));
    return 0.5 * (lower + upper);
}

float add_text(OverlayBatch& batch, float x, float y, const std::string& text, glm::vec4 color, float scale) {
    std::string line = text.substr(0, kMaxChars);
    for (char& c : line)
        if (c < 32 || c > 126) c = '?';  // the font has printable ASCII only
    // At most ~60 quads a character (the font's segments); 4 vertices a quad.
    static std::vector<EasyFontVertex> quads(kMaxChars * 64 * 4);
    unsigned char rgba[4] = {255, 255, 255, 255};
    const int count = stb_easy_font_print(0.0f, 0.0f, line.data(), rgba, quads.data(),
                                          static_cast<int>(quads.size() * sizeof(EasyFontVertex)));
    for (int q = 0; q < count; ++q) {
        const EasyFontVertex* v = &quads[static_cast<std::size_t>(q) * 4];
        auto at = [&](int k) { return glm::vec2(x + v[k].x * scale, y + v[k].y * scale); };
        batch.triangle(at(0), at(1), at(2), color);
        batch.triangle(at(0), at(2), at(3), color);
    }
    return static_cast<float>(stb_easy_font_width(line.data())) * scale;
}

float add_hud(OverlayBatch& batch, const HudText& hud, float scale) {
    const float pad = 6.0f * scale / 2.0f, line_h = kLineHeight * scale;
    const std::size_t rows = hud.lines.size() + hud.errors.size();
    if (rows == 0) return 0.0f;
    // The panel first (measured from the widest line), then the text on it.
    float width = 0.0f;
    for (const auto* list : {&hud.lines, &hud.errors})
        for (const std::string& s : *list) {
            std::string t = s.substr(0, kMaxChars);
            width = std::max(width, static_cast<float>(stb_easy_font_width(t.data())) * scale);
        }
    const float height = float(rows) * line_h + 2.0f * pad;
    batch.rect({0.0f, 0.0f}, {width + 2.0f * pad, height}, {0.0f, 0.0f, 0.0f, 0.6f});
    float y = pad;
    for (const std::string& s : hud.lines) {
        add_text(batch, pad, y, s, {1.0f, 1.0f, 1.0f, 1.0f}, scale);
        y += line_h;
    }
    for (const std::string& s : hud.errors) {
        add_text(batch, pad, y, s, {1.0f, 0.35f, 0.3f, 1.0f}, scale);
        y += line_h;
    }
    return height;
}

}  // namespace impossible::preview
