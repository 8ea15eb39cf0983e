// A headset's hidden-area mask: which pixels of an eye's image the lenses
// never show (OpenXR's XR_KHR_visibility_mask). The visible area is one
// simple polygon in normalised image coordinates (u from 0 at the left edge
// to 1 at the right, v from 0 at the top to 1 at the bottom); a pixel is
// hidden when its centre lies outside it. Both renderers ask these functions,
// so they mask exactly the same pixels (docs/headsets.md).
#pragma once

#include <cstdint>
#include <vector>

#include "math/polygon.hpp"

namespace impossible::math {

// Whether pixel (i, j) (column, row from the top) of a width × height image
// is hidden: its centre ((i + 0.5) / width, (j + 0.5) / height) is outside
// `visible` by the even-odd crossing rule on the row through the centre
// (an edge counts when one end is below the row and the other at or
// above). An empty polygon hides nothing.
bool pixel_hidden(const Polygon2& visible, int width, int height, int i, int j);

// The same for every pixel, rows from the top: 1 hidden, 0 visible. Equal
// to pixel_hidden pixel by pixel (the same arithmetic, one row at a time).
std::vector<std::uint8_t> hidden_pixels(const Polygon2& visible, int width, int height);

}  // namespace impossible::math
