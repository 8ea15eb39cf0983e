// Texture reads at level 0 (trace/texture_sample.hpp): nearest and linear,
// each wrap mode, inside the image, below 0 and beyond 1, against values
// worked out by hand from OpenGL's rules. Every texel byte and weight here is
// exact in binary, so the results are compared exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <initializer_list>

#include "trace/texture_sample.hpp"

namespace impossible::trace {
namespace {

using glm::dvec2;
using glm::dvec4;
namespace code = assets::sampler_code;

image::Pixels texel_image(int width, int height, std::initializer_list<std::uint8_t> bytes) {
    image::Pixels image;
    image.width = width;
    image.height = height;
    image.data = bytes;
    return image;
}

// 4 × 1, red 0, 85, 170, 255 (0, 1/3, 2/3, 1): the texel's index is 3 · red.
image::Pixels ramp() { return texel_image(4, 1, {0, 0, 0, 255, 85, 0, 0, 255, 170, 0, 0, 255, 255, 0, 0, 255}); }

// 2 × 2: top row red, green; bottom row blue, transparent white.
image::Pixels quadrant_image() {
    return texel_image(2, 2, {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 0});
}
const dvec4 kTexelRed(1, 0, 0, 1), kTexelGreen(0, 1, 0, 1), kTexelBlue(0, 0, 1, 1), kTexelClear(1, 1, 1, 0);

assets::Sampler sampler(int filter, int wrap_s, int wrap_t = code::kRepeat) {
    assets::Sampler s;
    s.mag_filter = filter;
    s.min_filter = code::kLinearMipmapLinear;  // never read at level 0
    s.wrap_s = wrap_s;
    s.wrap_t = wrap_t;
    return s;
}

// The red channel of the ramp, read with `filter` and `wrap` at s.
double ramp_at(int filter, int wrap, double s) { return sample_mip0(ramp(), sampler(filter, wrap), dvec2(s, 0.5)).r; }

// The texel of the ramp (its index) that nearest filtering reads at whole
// texel coordinate i (the centre of texel i, s = (i + 1/2) / 4).
int ramp_nearest_index(int wrap, int i) {
    return static_cast<int>(ramp_at(code::kNearest, wrap, (i + 0.5) / 4.0) * 3.0 + 0.5);
}

TEST(TextureSample, WrapTexelFollowsOpenGL) {
    // size 4: i = -5 … 8.
    const int repeat[] = {3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0};
    const int clamp[] = {0, 0, 0, 0, 0, 0, 1, 2, 3, 3, 3, 3, 3, 3};
    const int mirror[] = {3, 3, 2, 1, 0, 0, 1, 2, 3, 3, 2, 1, 0, 0};
    for (int i = -5; i <= 8; ++i) {
        EXPECT_EQ(wrap_texel(i, 4, code::kRepeat), repeat[i + 5]) << i;
        EXPECT_EQ(wrap_texel(i, 4, code::kClampToEdge), clamp[i + 5]) << i;
        EXPECT_EQ(wrap_texel(i, 4, code::kMirroredRepeat), mirror[i + 5]) << i;
    }
    // Size 1 always gives 0; far-off and non-finite coordinates stay in range.
    for (int wrap : {code::kRepeat, code::kClampToEdge, code::kMirroredRepeat}) {
        EXPECT_EQ(wrap_texel(-7.0, 1, wrap), 0);
        EXPECT_EQ(wrap_texel(1e300, 1, wrap), 0);
        const int far = wrap_texel(-3e17, 4, wrap);
        EXPECT_TRUE(far >= 0 && far < 4);
        EXPECT_EQ(wrap_texel(std::nan(""), 4, wrap), 0);
    }
}

TEST(TextureSample, NearestEachWrap) {
    // Inside: texel i at s in [i/4, (i+1)/4).
    for (int wrap : {code::kRepeat, code::kClampToEdge, code::kMirroredRepeat}) {
        EXPECT_EQ(ramp_at(code::kNearest, wrap, 0.0), 0.0);
        EXPECT_EQ(ramp_at(code::kNearest, wrap, 0.2499), 0.0);
        EXPECT_EQ(ramp_at(code::kNearest, wrap, 0.25), 85.0 / 255.0);
        EXPECT_EQ(ramp_at(code::kNearest, wrap, 0.9999), 1.0);
    }
    // Outside, by texel coordinate.
    EXPECT_EQ(ramp_nearest_index(code::kRepeat, -1), 3);
    EXPECT_EQ(ramp_nearest_index(code::kRepeat, 4), 0);
    EXPECT_EQ(ramp_nearest_index(code::kRepeat, 9), 1);
    EXPECT_EQ(ramp_nearest_index(code::kRepeat, -6), 2);
    EXPECT_EQ(ramp_nearest_index(code::kClampToEdge, -1), 0);
    EXPECT_EQ(ramp_nearest_index(code::kClampToEdge, 9), 3);
    EXPECT_EQ(ramp_nearest_index(code::kMirroredRepeat, 4), 3);
    EXPECT_EQ(ramp_nearest_index(code::kMirroredRepeat, 5), 2);
    EXPECT_EQ(ramp_nearest_index(code::kMirroredRepeat, 8), 0);
    EXPECT_EQ(ramp_nearest_index(code::kMirroredRepeat, -1), 0);
    EXPECT_EQ(ramp_nearest_index(code::kMirroredRepeat, -2), 1);
    EXPECT_EQ(ramp_nearest_index(code::kMirroredRepeat, -5), 3);
    // 1.0 exactly is texel 4: the first of the next tile (repeat), the last texel (clamp, mirror).
    EXPECT_EQ(ramp_at(code::kNearest, code::kRepeat, 1.0), 0.0);
    EXPECT_EQ(ramp_at(code::kNearest, code::kClampToEdge, 1.0), 1.0);
    EXPECT_EQ(ramp_at(code::kNearest, code::kMirroredRepeat, 1.0), 1.0);
}

TEST(TextureSample, LinearEachWrap) {
    const double third = 1.0 / 3.0;
    // At a texel's centre, that texel alone.
    for (int wrap : {code::kRepeat, code::kClampToEdge, code::kMirroredRepeat}) {
        EXPECT_EQ(ramp_at(code::kLinear, wrap, 0.125), 0.0);
        EXPECT_EQ(ramp_at(code::kLinear, wrap, 0.375), 85.0 / 255.0);
        // A quarter of the way from texel 1's centre to texel 2's.
        EXPECT_NEAR(ramp_at(code::kLinear, wrap, 0.4375), 0.75 * third + 0.25 * 2.0 * third, 1e-15);
    }
    // s = 0 (x - 1/2 = -1/2): texels -1 and 0, half each.
    EXPECT_NEAR(ramp_at(code::kLinear, code::kRepeat, 0.0), 0.5 * 1.0 + 0.5 * 0.0, 1e-15);
    EXPECT_EQ(ramp_at(code::kLinear, code::kClampToEdge, 0.0), 0.0);
    EXPECT_EQ(ramp_at(code::kLinear, code::kMirroredRepeat, 0.0), 0.0);
    // s = 1.25 (x - 1/2 = 4.5): texels 4 and 5, half each.
    EXPECT_NEAR(ramp_at(code::kLinear, code::kRepeat, 1.25), 0.5 * (0.0 + third), 1e-15);
    EXPECT_EQ(ramp_at(code::kLinear, code::kClampToEdge, 1.25), 1.0);
    EXPECT_NEAR(ramp_at(code::kLinear, code::kMirroredRepeat, 1.25), 0.5 * (1.0 + 2.0 * third), 1e-15);
    // s = -0.3 (x - 1/2 = -1.7): texels -2 (weight 0.7) and -1 (0.3).
    EXPECT_NEAR(ramp_at(code::kLinear, code::kRepeat, -0.3), 0.7 * 2.0 * third + 0.3 * 1.0, 1e-15);
    EXPECT_EQ(ramp_at(code::kLinear, code::kClampToEdge, -0.3), 0.0);
    EXPECT_NEAR(ramp_at(code::kLinear, code::kMirroredRepeat, -0.3), 0.7 * third + 0.3 * 0.0, 1e-15);
}

TEST(TextureSample, RowZeroIsTheTopAndTGrowsDown) {
    const image::Pixels image = quadrant_image();
    const assets::Sampler nearest = sampler(code::kNearest, code::kRepeat, code::kRepeat);
    EXPECT_EQ(sample_mip0(image, nearest, dvec2(0.25, 0.25)), kTexelRed);
    EXPECT_EQ(sample_mip0(image, nearest, dvec2(0.75, 0.25)), kTexelGreen);
    EXPECT_EQ(sample_mip0(image, nearest, dvec2(0.25, 0.75)), kTexelBlue);
    EXPECT_EQ(sample_mip0(image, nearest, dvec2(0.75, 0.75)), kTexelClear);
    EXPECT_EQ(sample_mip0(image, nearest, dvec2(-0.25, -0.25)), kTexelClear);  // repeat: the tile up and left
    EXPECT_EQ(sample_mip0(image, nearest, dvec2(2.25, -1.75)), kTexelRed);
}

TEST(TextureSample, LinearTwoAxesWithTheirOwnWraps) {
    const image::Pixels image = quadrant_image();
    // The centre: all four equally.
    EXPECT_EQ(sample_mip0(image, sampler(code::kLinear, code::kRepeat), dvec2(0.5, 0.5)),
              0.25 * (kTexelRed + kTexelGreen + kTexelBlue + kTexelClear));
    // (0.375, 0.125): x - 1/2 = 0.25 (columns 0 and 1, weighted 3/4 and
    // 1/4), y - 1/2 = -0.25 (rows -1, by repeat row 1, and 0, weighted 1/4
    // and 3/4).
    const dvec4 expected =
        0.75 * 0.25 * kTexelBlue + 0.25 * 0.25 * kTexelClear + 0.75 * 0.75 * kTexelRed + 0.25 * 0.75 * kTexelGreen;
    EXPECT_EQ(sample_mip0(image, sampler(code::kLinear, code::kRepeat, code::kRepeat), dvec2(0.375, 0.125)), expected);
    EXPECT_EQ(expected, dvec4(0.625, 0.25, 0.25, 0.9375));
    // Row -1 clamped (or mirrored) is row 0 itself.
    for (int wrap_t : {code::kClampToEdge, code::kMirroredRepeat}) {
        EXPECT_EQ(sample_mip0(image, sampler(code::kLinear, code::kRepeat, wrap_t), dvec2(0.375, 0.125)),
                  0.75 * kTexelRed + 0.25 * kTexelGreen);
    }
    // The bottom-left corner (0, 1): columns -1, 0 and rows 1, 2, half each.
    EXPECT_EQ(sample_mip0(image, sampler(code::kLinear, code::kRepeat, code::kClampToEdge), dvec2(0.0, 1.0)),
              0.5 * kTexelBlue + 0.5 * kTexelClear);
    EXPECT_EQ(sample_mip0(image, sampler(code::kLinear, code::kRepeat, code::kMirroredRepeat), dvec2(0.0, 1.0)),
              0.5 * kTexelBlue + 0.5 * kTexelClear);
    EXPECT_EQ(sample_mip0(image, sampler(code::kLinear, code::kRepeat, code::kRepeat), dvec2(0.0, 1.0)),
              0.25 * (kTexelRed + kTexelGreen + kTexelBlue + kTexelClear));
    EXPECT_EQ(sample_mip0(image, sampler(code::kLinear, code::kClampToEdge, code::kClampToEdge), dvec2(0.0, 1.0)),
              kTexelBlue);
}

TEST(TextureSample, MagFilterDecidesMinFilterIsNotRead) {
    const image::Pixels image = quadrant_image();
    assets::Sampler s = sampler(code::kNearest, code::kRepeat);
    s.min_filter = code::kLinear;
    EXPECT_EQ(sample_mip0(image, s, dvec2(0.3, 0.3)), kTexelRed);
    s.mag_filter = code::kLinear;
    s.min_filter = code::kNearest;
    EXPECT_NE(sample_mip0(image, s, dvec2(0.3, 0.3)), kTexelRed);
}

TEST(TextureSample, EmptyImageIsWhite) {
    EXPECT_EQ(sample_mip0(image::Pixels{}, assets::Sampler{}, dvec2(0.3, 0.3)), dvec4(1.0));
}

}  // namespace
}  // namespace impossible::trace
