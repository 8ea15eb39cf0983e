// Decodes PNG and JPEG bytes (stb_image from Debian's libstb): the one place
// where the program decodes a picture, for textures and for PNG files alike.
#pragma once

#include <cstddef>
#include <string>

#include "base/result.hpp"
#include "image/pixels.hpp"

namespace impossible::image {

// What the bytes are, by their first bytes (not by a file name or mimeType).
enum class ImageFormat { Png, Jpeg, Other };
ImageFormat sniff_image(const unsigned char* bytes, std::size_t size);

// The image's size without decoding it; an error when it is not PNG or JPEG,
// its header is broken, or a side is beyond `max_side`.
struct ImageSize {
    int width = 0;
    int height = 0;
    std::size_t texels() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
};
Result<ImageSize> image_size(const unsigned char* bytes, std::size_t size, int max_side);

// Decodes PNG or JPEG bytes to RGBA8 (grey and RGB get alpha 255, 16-bit
// channels are reduced to 8 bits), for textures. Errors are a reason that
// follows the image's name: "is neither PNG nor JPEG data", "is 9000 x 4
// pixels; ...", "could not be decoded (bad zlib header)".
Result<Pixels> decode_image(const unsigned char* bytes, std::size_t size, int max_side);

// Decodes bytes to 8-bit pixels keeping grey as grey (1 channel) and
// everything else as RGB (3), dropping alpha: how PNG files written by the
// program are read back. The error is stb_image's reason alone.
Result<Pixels> decode_grey_or_rgb(const unsigned char* bytes, std::size_t size);

}  // namespace impossible::image
