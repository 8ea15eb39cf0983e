// Decodes PNG and JPEG bytes: the one place where the program decodes a
// picture, for textures and for PNG files alike. The format is told by the
// signature; its structure is read here first (png_check, jpeg_check), so a
// fault is named as the PNG or JPEG fault it is, then stb_image decodes
// (stb_image_impl.cpp: allocations zeroed; png_palette.cpp: palette indices
// past the PLTE chunk). The same bytes always give the same pixels.
#pragma once

#include <cstddef>
#include <string>

#include "base/result.hpp"
#include "image/pixels.hpp"

namespace impossible::image {

// What the bytes are, by their first bytes (not by a file name or mimeType).
enum class ImageFormat { Png, Jpeg, Other };
ImageFormat sniff_image(const unsigned char* bytes, std::size_t size);

// The image's size from its header (a PNG's IHDR, a JPEG's first SOF),
// without decoding it; an error when it is not PNG or JPEG, its header is
// broken, or a side is beyond `max_side` ("is 30000 x 30000 pixels; the limit
// is 8192 pixels on a side").
struct ImageSize {
    int width = 0;
    int height = 0;
    std::size_t texels() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
};
Result<ImageSize> image_size(const unsigned char* bytes, std::size_t size, int max_side);

// Decodes PNG or JPEG bytes to RGBA8 (grey and RGB get alpha 255, 16-bit
// channels are reduced to 8 bits), for textures. Errors are a reason that
// follows the image's name: "is neither PNG nor JPEG data", "is 9000 x 4
// pixels; ...", "could not be decoded as PNG: it has a damaged chunk IDAT
// (its CRC does not match its data)", "could not be decoded as JPEG: it is
// truncated (it ends before its EOI marker)", "could not be decoded as PNG:
// pixel (2, 0) has the palette index 255, past the 2 entries of its PLTE
// chunk", "could not be decoded as PNG: bad zlib header" (stb_image's).
Result<Pixels> decode_image(const unsigned char* bytes, std::size_t size, int max_side);

// Decodes PNG bytes to 8-bit pixels keeping grey as grey (1 channel) and
// everything else as RGB (3), dropping alpha: how PNG files written by the
// program are read back, after check_png. The error is the reason alone
// (stb_image's, or png_palette's).
Result<Pixels> decode_grey_or_rgb(const unsigned char* bytes, std::size_t size);

}  // namespace impossible::image
