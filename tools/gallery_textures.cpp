// The gallery's pictures (gallery_assets.hpp), drawn pixel by pixel with
// integer arithmetic so that they are the same everywhere.
#include "gallery_assets.hpp"

#include <array>
#include <cstdlib>

#include <stb_image_write.h>

namespace impossible::tools::gallery {

namespace {

using Rgb = std::array<int, 3>;

// A small integer hash (for the variation between bricks, boards and pixels).
std::uint32_t hash(std::uint32_t a, std::uint32_t b = 0) {
    std::uint32_t h = a * 0x9E3779B1u ^ (b + 0x7F4A7C15u) * 0x85EBCA77u;
    h ^= h >> 15;
    h *= 0x2C1B3C6Du;
    h ^= h >> 12;
    h *= 0x297A2D39u;
    h ^= h >> 15;
    return h;
}

// A value in [-amount, amount] from the hash of (a, b).
int jitter(std::uint32_t a, std::uint32_t b, int amount) {
    return static_cast<int>(hash(a, b) % static_cast<std::uint32_t>(2 * amount + 1)) - amount;
}

Picture blank(int size, int channels) {
    Picture p;
    p.width = size;
    p.height = size;
    p.channels = channels;
    p.pixels.assign(static_cast<std::size_t>(size) * size * channels, 0);
    return p;
}

std::uint8_t clamp_byte(int v) { return static_cast<std::uint8_t>(v < 0 ? 0 : v > 255 ? 255 : v); }

void set(Picture& p, int x, int y, const Rgb& c, int alpha = 255) {
    if (x < 0 || y < 0 || x >= p.width || y >= p.height) return;
    const std::size_t at = (static_cast<std::size_t>(y) * p.width + x) * p.channels;
    for (std::size_t k = 0; k < 3; ++k) p.pixels[at + k] = clamp_byte(c[k]);
    if (p.channels == 4) p.pixels[at + 3] = clamp_byte(alpha);
}

Rgb add(const Rgb& c, int d) { return {c[0] + d, c[1] + d, c[2] + d}; }

// c0 + (c1 - c0) · num / den, per channel.
Rgb mix(const Rgb& c0, const Rgb& c1, int num, int den) {
    Rgb out{};
    for (std::size_t k = 0; k < 3; ++k) out[k] = c0[k] + (c1[k] - c0[k]) * num / den;
    return out;
}

// 5 × 7 glyphs, rows from the top, bit 4 the leftmost column.
constexpr std::array<std::uint8_t, 7> kGlyphF = {0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x10};
constexpr std::array<std::uint8_t, 7> kGlyph7 = {0x1F, 0x1F, 0x03, 0x06, 0x0C, 0x0C, 0x0C};  // bold

bool glyph_bit(const std::array<std::uint8_t, 7>& glyph, int column, int row) {
    return column >= 0 && column < 5 && row >= 0 && row < 7 &&
           (glyph[static_cast<std::size_t>(row)] >> (4 - column) & 1) != 0;
}

// Draws a glyph with its top-left corner at (x0, y0), each glyph cell
// `scale` pixels square, with an outline one pixel wide in `outline`.
void draw_glyph(Picture& p, const std::array<std::uint8_t, 7>& glyph, int x0, int y0, int scale, const Rgb& ink,
                const Rgb& outline) {
    const auto inked = [&](int x, int y) {
        const int dx = x - x0;
        const int dy = y - y0;
        return dx >= 0 && dy >= 0 && glyph_bit(glyph, dx / scale, dy / scale);
    };
    for (int y = y0 - 1; y <= y0 + 7 * scale; ++y) {
        for (int x = x0 - 1; x <= x0 + 5 * scale; ++x) {
            if (inked(x, y)) {
                set(p, x, y, ink);
            } else if (inked(x - 1, y) || inked(x + 1, y) || inked(x, y - 1) || inked(x, y + 1)) {
                set(p, x, y, outline);
            }
        }
    }
}

// A triangle wave of period 16 with values 0..8.
int wave(int t) {
    const int m = ((t % 16) + 16) % 16;
    return m < 8 ? m : 16 - m;
}

}  // namespace

Picture brick_wall() {
    Picture p = blank(64, 3);
    const Rgb mortar = {196, 190, 178};
    const Rgb brick = {158, 64, 46};
    for (int y = 0; y < 64; ++y) {
        const int course = y / 16;
        const int shift = (course % 2) * 16;  // running bond: every other course half a brick over
        for (int x = 0; x < 64; ++x) {
            const int along = (x + shift) % 64;
            const int n = jitter(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), 5);
            if (y % 16 < 2 || along % 32 < 2) {
                set(p, x, y, add(mortar, n));
            } else {
                const int which =
                    jitter(static_cast<std::uint32_t>(course), static_cast<std::uint32_t>(along / 32), 18);
                Rgb c = add(brick, which + n);
                if (y % 16 == 2) c = add(c, 14);  // a lit upper edge
                if (y % 16 == 15) c = add(c, -16);
                set(p, x, y, c);
            }
        }
    }
    return p;
}

Picture floor_tiles() {
    Picture p = blank(64, 3);
    const Rgb grout = {88, 88, 94};
    const Rgb cream = {226, 218, 198};
    const Rgb slate = {104, 122, 150};
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x) {
            const int n = jitter(static_cast<std::uint32_t>(x) + 100, static_cast<std::uint32_t>(y), 4);
            const int u = x % 32;
            const int v = y % 32;
            if (u < 2 || v < 2) {
                set(p, x, y, add(grout, n));
                continue;
            }
            Rgb c = ((x / 32 + y / 32) % 2 == 0) ? cream : slate;
            if (u == 2 || v == 2) c = add(c, 18);  // bevel: light on the top and left
            if (u == 31 || v == 31) c = add(c, -22);
            // A small diamond inlaid at the tile's centre.
            if (std::abs(u - 16) + std::abs(v - 16) <= 4) c = mix(c, {170, 60, 50}, 3, 4);
            set(p, x, y, add(c, n));
        }
    }
    return p;
}

Picture wood_planks() {
    Picture p = blank(64, 3);
    for (int board = 0; board < 4; ++board) {
        const auto b = static_cast<std::uint32_t>(board);
        const Rgb base = add({150, 102, 60}, jitter(b, 7, 16));
        const int joint = static_cast<int>(hash(b, 11) % 64);  // where this board's end joint is
        for (int y = 0; y < 64; ++y) {
            for (int i = 0; i < 16; ++i) {
                const int x = 16 * board + i;
                Rgb c = add(base, jitter(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y) + 500, 4));
                for (int line = 0; line < 3; ++line) {
                    const auto l = static_cast<std::uint32_t>(line);
                    const int at = 3 + 4 * line + static_cast<int>(hash(b, l) % 3) +
                                   wave(y + static_cast<int>(hash(b, l + 20) % 16)) / 4;
                    if (i == at) c = add(c, -26);  // a grain line wandering along the board
                }
                if (i == 0) c = add(c, -50);  // the gap between boards
                if (i == 1) c = add(c, 12);
                if (y == joint) c = add(c, -45);
                set(p, x, y, c);
            }
        }
    }
    return p;
}

Picture mural() {
    Picture p = blank(128, 3);
    for (int y = 0; y < 128; ++y) {
        for (int x = 0; x < 128; ++x) {
            Rgb c;
            if (y < 96) {
                c = mix({70, 120, 200}, {190, 220, 245}, y, 96);  // sky, lighter towards the horizon
            } else {
                c = mix({90, 160, 70}, {50, 110, 40}, y - 96, 32);  // meadow
            }
            const int dx = x - 100;
            const int dy = y - 24;
            if (dx * dx + dy * dy <= 13 * 13) c = {250, 214, 60};  // the sun, top right
            // An arrow pointing up: a shaft and a head.
            const bool shaft = x >= 56 && x < 72 && y >= 44 && y < 110;
            const bool head = y >= 14 && y < 44 && std::abs(2 * x - 127) <= 2 * (y - 14) + 2;
            if (shaft || head) c = {200, 40, 40};
            if (x < 3 || y < 3 || x >= 125 || y >= 125) c = {70, 45, 30};  // frame
            set(p, x, y, c);
        }
    }
    draw_glyph(p, kGlyphF, 12, 40, 5, {255, 255, 255}, {20, 20, 20});
    return p;
}

Picture crate_side() {
    Picture p = blank(64, 3);
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x) {
            const int board = y / 16;
            const int n = jitter(static_cast<std::uint32_t>(x) + 900, static_cast<std::uint32_t>(y), 5);
            Rgb c = add({176, 130, 78}, jitter(static_cast<std::uint32_t>(board), 3, 10) + n);
            if (y % 16 == 0) c = add(c, -55);                                            // gaps between boards
            if (wave(x + 5 * board) == 0 && y % 16 > 4 && y % 16 < 12) c = add(c, -20);  // knots of grain
            const bool frame = x < 6 || y < 6 || x >= 58 || y >= 58;
            if (frame) c = add({120, 82, 46}, n);
            if (frame && (x == 6 || y == 6 || x == 57 || y == 57)) c = add(c, -30);
            set(p, x, y, c);
        }
    }
    draw_glyph(p, kGlyph7, 22, 18, 4, {30, 28, 26}, {150, 108, 64});
    return p;
}

Picture plant_leaves() {
    Picture p = blank(128, 4);
    // Everything starts transparent, its colour a dark green so that a
    // filtered edge darkens towards the leaf colour rather than black.
    for (int y = 0; y < 128; ++y) {
        for (int x = 0; x < 128; ++x) set(p, x, y, {30, 70, 30}, 0);
    }
    for (int y = 30; y < 128; ++y) {
        for (int x = 62; x < 66; ++x) set(p, x, y, {80, 100, 40});  // the stem
    }
    // Pairs of leaves rising outwards, smaller towards the top, and one at the tip.
    for (int pair = 0; pair < 5; ++pair) {
        const int cy = 112 - 18 * pair;
        const int a = 24 - 3 * pair;  // half length
        const int b = 6;              // half width
        const Rgb leaf = mix({40, 120, 40}, {110, 180, 60}, pair, 4);
        for (const int side : {-1, 1}) {
            const int cx = 64 + side * (a + 2);
            for (int y = cy - a; y <= cy + b + 1; ++y) {
                for (int x = cx - a; x <= cx + a; ++x) {
                    const int dx = x - cx;
                    const int rise = std::abs(x - 64) / 3;  // the leaf tilts up away from the stem
                    const int dy = y - cy + rise;
                    if (dx * dx * b * b + dy * dy * a * a > a * a * b * b) continue;
                    Rgb c = add(leaf, jitter(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y) + 77, 8));
                    if (dy == 0) c = add(c, 40);  // the midrib
                    set(p, x, y, c);
                }
            }
        }
    }
    for (int y = 6; y < 40; ++y) {
        for (int x = 54; x < 74; ++x) {
            const int dx = x - 64;
            const int dy = y - 23;
            if (dx * dx * 17 * 17 + dy * dy * 8 * 8 > 8 * 8 * 17 * 17) continue;
            Rgb c = add({120, 190, 70}, jitter(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y) + 99, 8));
            if (dx == 0) c = add(c, 40);
            set(p, x, y, c);
        }
    }
    return p;
}

std::vector<unsigned char> png_of(const Picture& picture) {
    std::vector<unsigned char> out;
    const auto append = [](void* context, void* data, int size) {
        auto* bytes = static_cast<std::vector<unsigned char>*>(context);
        const auto* begin = static_cast<const unsigned char*>(data);
        bytes->insert(bytes->end(), begin, begin + size);
    };
    stbi_write_png_to_func(append, &out, picture.width, picture.height, picture.channels, picture.pixels.data(),
                           picture.width * picture.channels);
    return out;
}

}  // namespace impossible::tools::gallery
