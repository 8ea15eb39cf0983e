// Palette PNGs (colour type 3) whose PLTE chunk has fewer entries than their
// bit depth can index. stb_image expands indices through a table of 256
// colours of which it sets only the PLTE's, so a pixel whose index is past
// them took its colour from uninitialised stack memory: another picture on
// every run. Such a PNG is decoded here instead, exactly: its PLTE is
// replaced by one of 256 entries that gives each index its own value, then
// each pixel's index is looked up in the real palette (its tRNS alpha
// included), and an index past the PLTE is an error that names the first
// pixel that has one.
#pragma once

#include <cstddef>
#include <optional>

#include "base/result.hpp"
#include "image/pixels.hpp"

namespace impossible::image {

// The pixels of such a PNG (whose chunks were checked) in `want` channels (3
// or 4) or why there are none, after "could not be decoded as PNG: ":
// "pixel (2, 0) has the palette index 255, past the 2 entries of its PLTE
// chunk", "it has more than one PLTE chunk", "its tRNS chunk has 3 entries,
// more than the 2 of its PLTE chunk", or stb_image's reason. Nothing for
// other images, which stb_image decodes as they are.
std::optional<Result<Pixels>> decode_short_palette(const unsigned char* bytes, std::size_t size, int want);

}  // namespace impossible::image
