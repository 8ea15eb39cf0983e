// Decodes the PNG and JPEG images of glTF textures and room faces with
// stb_image into layout::Image (8-bit RGBA, rows from the top).
#pragma once

#include <cstddef>
#include <string>

#include "base/result.hpp"
#include "layout/layout.hpp"

namespace impossible::layout::detail {

// What the bytes are, by their first bytes (not by a file name or mimeType).
enum class ImageFormat { Png, Jpeg, Other };
ImageFormat sniff_image(const unsigned char* bytes, std::size_t size);

// The image's size without decoding it; an error when it is not PNG or JPEG,
// its header is broken, or a side is beyond limits::kMaxImageSide.
struct ImageSize {
    int width = 0;
    int height = 0;
    std::size_t texels() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
};
Result<ImageSize> image_size(const unsigned char* bytes, std::size_t size);

// Decodes PNG or JPEG bytes to RGBA8 (grey and RGB get alpha 255, 16-bit
// channels are reduced to 8 bits). Errors are a reason that follows the
// image's name: "is neither PNG nor JPEG data", "is 9000 x 4 pixels; ...",
// "could not be decoded (bad zlib header)".
Result<Image> decode_image(const unsigned char* bytes, std::size_t size);

}  // namespace impossible::layout::detail
