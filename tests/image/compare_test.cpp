// The metrics of `impossible compare` on small synthetic pictures.
#include <gtest/gtest.h>

#include <cmath>

#include "image/compare.hpp"

namespace impossible::image {
namespace {

// A width × height picture: id `left` in columns < edge, `right` from there
// on; colour grey 100 on the left, 200 on the right.
Image split(int width, int height, int edge, std::uint8_t left = 1, std::uint8_t right = 2) {
    Image p;
    p.width = width;
    p.height = height;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const bool l = x < edge;
            p.ids.push_back(l ? left : right);
            for (int c = 0; c < 3; ++c) p.rgb.push_back(l ? 100 : 200);
        }
    }
    return p;
}

std::uint8_t& red(Image& p, int x, int y) { return p.rgb[3 * (static_cast<size_t>(y) * p.width + x)]; }

TEST(ImageCompare, IdenticalPicturesAgreeCompletely) {
    const Image a = split(12, 8, 5);
    ASSERT_FALSE(incomparable(a, a));
    const Comparison c = compare_pictures(a, a);
    EXPECT_EQ(c.pixels, 96);
    EXPECT_TRUE(std::isinf(c.psnr_db));
    EXPECT_EQ(c.max_error, 0);
    EXPECT_TRUE(c.has_ids);
    EXPECT_EQ(c.id_mismatches, 0);
    EXPECT_EQ(c.id_mismatch_percent, 0.0);
    EXPECT_EQ(summary_line(c).find("psnr_db=inf max_error=0 id_mismatches=0"), 10u) << summary_line(c);
}

TEST(ImageCompare, AnEdgeMovedByOnePixelIsToleratedAndByTwoIsNot) {
    const Image a = split(12, 8, 5);
    EXPECT_EQ(compare_pictures(a, split(12, 8, 6)).id_mismatches, 0);
    EXPECT_EQ(compare_pictures(a, split(12, 8, 4)).id_mismatches, 0);
    // Moved to 7: A's column 5 (id 2) has only id 1 near it in B, and B's
    // column 6 (id 1) only id 2 near it in A: two pixels a row.
    const Comparison two = compare_pictures(a, split(12, 8, 7));
    EXPECT_EQ(two.id_mismatches, 2 * 8);
    EXPECT_DOUBLE_EQ(two.id_mismatch_percent, 100.0 * 16 / 96);
    const std::vector<std::uint8_t> mask = id_mismatch_mask(12, 8, a.ids, split(12, 8, 7).ids);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 12; ++x) EXPECT_EQ(mask[y * 12 + x], (x == 5 || x == 6) ? 1 : 0) << x << "," << y;
}

TEST(ImageCompare, MismatchesAreFoundInBothDirections) {
    Image a = split(10, 10, 10);  // all id 1
    Image b = a;
    a.ids[5 * 10 + 5] = 3;  // a lone id only A has
    EXPECT_EQ(compare_pictures(a, b).id_mismatches, 1);
    EXPECT_EQ(compare_pictures(b, a).id_mismatches, 1);
    // An id at the border is looked for in the clipped neighbourhood only.
    b.ids[0] = 4;
    EXPECT_EQ(compare_pictures(a, b).id_mismatches, 2);
}

TEST(ImageCompare, PsnrAndMaxErrorFollowTheirDefinitions) {
    const Image a = split(10, 10, 10);
    Image b = a;
    red(b, 3, 4) += 10;  // one channel of one pixel off by 10
    const Comparison c = compare_pictures(a, b);
    EXPECT_EQ(c.max_error, 10);
    // MSE = 10² / 300 samples.
    EXPECT_NEAR(c.psnr_db, 10.0 * std::log10(255.0 * 255.0 * 300.0 / 100.0), 1e-9);
}

TEST(ImageCompare, InteriorStatisticsIgnoreEdgePixels) {
    const Image a = split(12, 8, 5);
    Image b = a;
    red(b, 4, 2) = 0;   // next to the edge: not interior
    red(b, 9, 3) += 3;  // well inside the right part
    const Comparison c = compare_pictures(a, b);
    EXPECT_EQ(c.max_error, 100);
    EXPECT_EQ(c.interior_max_error, 3);
    // Interior: columns 0..3 and 6..11, every row (neighbourhoods are
    // clipped at the border, not counted as different).
    EXPECT_EQ(c.interior_pixels, 10 * 8);
    EXPECT_NEAR(c.interior_psnr_db, 10.0 * std::log10(255.0 * 255.0 * 240.0 / 9.0), 1e-9);
}

TEST(ImageCompare, WithoutIdMapsOnlyColourIsCompared) {
    Image a = split(6, 4, 3), b = split(6, 4, 3);
    a.ids.clear();
    b.ids.clear();
    const Comparison c = compare_pictures(a, b);
    EXPECT_FALSE(c.has_ids);
    EXPECT_EQ(summary_line(c).find("id_mismatches"), std::string::npos);
}

TEST(ImageCompare, IncomparablePicturesAreNamed) {
    const Image a = split(6, 4, 3);
    EXPECT_TRUE(incomparable(a, split(6, 5, 3)));
    EXPECT_TRUE(incomparable(a, split(7, 4, 3)));
    Image no_ids = a;
    no_ids.ids.clear();
    EXPECT_TRUE(incomparable(a, no_ids));
    Image short_ids = a;
    short_ids.ids.pop_back();
    EXPECT_TRUE(incomparable(short_ids, short_ids));
    EXPECT_FALSE(incomparable(a, a));
}

TEST(ImageCompare, DiffPictureMarksIdMismatchesRedAndAmplifiesColourErrors) {
    const Image a = split(12, 8, 5);
    Image b = split(12, 8, 7);
    red(b, 10, 4) = 205;  // 5 off
    const std::vector<std::uint8_t> diff = diff_picture(a, b);
    ASSERT_EQ(diff.size(), 12u * 8u * 3u);
    auto px = [&](int x, int y, int c) { return diff[3 * (static_cast<size_t>(y) * 12 + x) + c]; };
    EXPECT_EQ(px(5, 3, 0), 255);  // mismatched id
    EXPECT_EQ(px(5, 3, 1), 0);
    // Equal pixel: grey = luminance / 3 = 200 / 3 → 67, no green added.
    EXPECT_EQ(px(11, 0, 0), 67);
    EXPECT_EQ(px(11, 0, 1), 67);
    EXPECT_EQ(px(10, 4, 0), 67);
    EXPECT_EQ(px(10, 4, 1), 67 + 8 * 5);
}

}  // namespace
}  // namespace impossible::image

namespace impossible::image {
namespace {

// Issue 38: a checker's edge inside one id, one pixel apart in the two
// pictures (as render and trace put it): the interior sees the tiles'
// contrast, the flat pixels leave the edge out and see a correct frame.
TEST(ImageCompare, FlatStatisticsLeaveOutColourEdges) {
    Image a = split(12, 8, 12);  // one id, grey 100
    Image b = a;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 12; ++x) {
            if (x >= 6) red(a, x, y) = 239;
            if (x >= 7) red(b, x, y) = 239;
        }
    red(b, 1, 1) += 2;  // a shading difference away from the edge
    const Comparison c = compare_pictures(a, b);
    EXPECT_EQ(c.interior_max_error, 139);
    EXPECT_EQ(c.flat_max_error, 2);
    // Columns 5..7 lie within one pixel of an edge in a or in b.
    EXPECT_EQ(c.flat_pixels, 9 * 8);
    const std::string line = summary_line(c);
    EXPECT_NE(line.find(" interior_max_error=139 flat_pixels=72 flat_psnr_db="), std::string::npos) << line;
    EXPECT_EQ(line.substr(line.size() - 17), " flat_max_error=2") << line;
}

}  // namespace
}  // namespace impossible::image
