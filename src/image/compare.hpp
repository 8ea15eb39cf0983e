// Comparing two frames of the same view (a rasterised one and a traced one),
// for `impossible compare`: cell-id agreement with a one-pixel edge
// tolerance, colour PSNR and maximum channel error, and a diff picture.
// Pure functions on pixel buffers; the command does the file I/O.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "image/image.hpp"

namespace impossible::image {

// Why two pictures cannot be compared (sizes differ, buffers of the wrong
// size, an id map on one side only), or nothing.
std::optional<std::string> incomparable(const Image& a, const Image& b);

// Per pixel, 1 where the ids disagree beyond the edge tolerance: pixel p is
// wrong when no pixel of B's map within one pixel of p (its 3×3
// neighbourhood, clipped at the image border) has A's id at p, or no pixel of
// A's map within one pixel of p has B's id at p. So an edge that moved by one
// pixel counts nothing; one that moved by two counts.
std::vector<std::uint8_t> id_mismatch_mask(int width, int height, const std::vector<std::uint8_t>& ids_a,
                                           const std::vector<std::uint8_t>& ids_b);

struct Comparison {
    long pixels = 0;
    // Colour, over every pixel and channel. PSNR = 10·log10(255² / MSE);
    // +infinity for identical images.
    double psnr_db = 0.0;
    int max_error = 0;  // largest |a - b| of any channel, 0..255
    bool has_ids = false;
    // The rest needs id maps.
    long id_mismatches = 0;
    double id_mismatch_percent = 0.0;
    // Colour over the "interior" pixels: those whose 3×3 neighbourhood holds
    // one id, the same in both maps (no silhouette edge near them), so that
    // edge aliasing does not hide a shading difference.
    long interior_pixels = 0;
    double interior_psnr_db = 0.0;
    int interior_max_error = 0;
    // The interior less the pixels on a colour edge (a checker's or a
    // texture's: a neighbour differs by more than 8 levels in A or in B),
    // where a sub-pixel difference between two correct frames flips a pixel
    // to the other tile: on a correct frame its max error is small while
    // interior_max_error can reach the tiles' contrast.
    long flat_pixels = 0;
    double flat_psnr_db = 0.0;
    int flat_max_error = 0;
};

// The pictures must be comparable (see incomparable()).
Comparison compare_pictures(const Image& a, const Image& b);

// A picture of the differences, same size, rgb: A's luminance dimmed to a
// third as the grey background, the largest channel error of each pixel
// added ×8 to green (clamped), and pixels with mismatched ids pure red.
std::vector<std::uint8_t> diff_picture(const Image& a, const Image& b);

// "key=value" pairs on one line (no newline): pixels, psnr_db, max_error and,
// with ids, id_mismatches, id_mismatch_pct, interior_pixels,
// interior_psnr_db, interior_max_error, flat_pixels, flat_psnr_db,
// flat_max_error (new keys only ever added at the end). PSNR of identical images is "inf".
std::string summary_line(const Comparison& c);

}  // namespace impossible::image
