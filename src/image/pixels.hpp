// The one decoded picture type: a texture decoded from PNG or JPEG, a PNG
// file read back, a plan drawn on the CPU. (A stereo frame, with its cell
// ids, is image::Image in image.hpp.)
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace impossible::image {

// 8-bit channels, rows from the top of the picture down. Texel values are
// used as stored: the renderers write shaded colours to 8-bit images without
// an sRGB transfer, so a texel multiplies the colour as the factors and face
// colours do (docs/choices.md).
struct Pixels {
    int width = 0;
    int height = 0;
    int channels = 4;                // 1 grey, 3 RGB or 4 RGBA
    int bit_depth = 8;               // of the file it came from (the channels here are always 8-bit)
    std::vector<std::uint8_t> data;  // width × height × channels bytes

    std::size_t texels() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
};

}  // namespace impossible::image
