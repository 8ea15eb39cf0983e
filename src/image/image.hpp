// The one image type of the program: a side-by-side stereo frame as the
// rasteriser draws it, the tracer computes it, and PNG files and comparisons
// hold it.
#pragma once

#include <cstdint>
#include <vector>

namespace impossible::image {

// Left eye in the left half, rows from the top. `rgb` is 3 bytes a pixel;
// `ids` one cell id a pixel (layout-format.md), or empty where a frame has
// no id map (a colour PNG read on its own).
struct Image {
    int width = 0;  // 2 × eye width for a stereo frame
    int height = 0;
    std::vector<std::uint8_t> rgb;  // width × height × 3
    std::vector<std::uint8_t> ids;  // width × height, or empty
};

}  // namespace impossible::image
