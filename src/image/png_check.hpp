// Checks a PNG file's structure before decoding it (stb_image checks no CRCs,
// decodes 16-bit images silently to 8 bits and names most faults "unknown
// image type"): signature, chunk types, CRCs, the header, a pixel limit.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "base/result.hpp"

namespace impossible::image {

// Images of more pixels are refused before decoding (the largest frame the
// program writes is 2 × 8192 × 8192).
inline constexpr std::uint64_t kMaxPngPixels = 2ull * 8192 * 8192;

struct PngHeader {
    std::uint32_t width = 0, height = 0;
    int bit_depth = 0;    // 1, 2, 4, 8 or 16
    int colour_type = 0;  // 0 grey, 2 rgb, 3 palette, 4 grey + alpha, 6 rgba
};

// The header of a well-formed PNG, or why it is not one, in words ("is not a
// PNG file", "has a damaged chunk 'IDAT' (its CRC does not match)"):
// png_header, the pixel limit, then check_png_chunks.
Result<PngHeader> check_png(const std::vector<unsigned char>& bytes);

// The signature and the first chunk, which must be a whole IHDR of a picture
// with pixels; no size limit. The error is check_png's words.
Result<PngHeader> png_header(const unsigned char* bytes, std::size_t size);

// Every chunk from the first to IEND: whole, a type of four letters, its CRC
// right. The error is check_png's words.
Result<void> check_png_chunks(const unsigned char* bytes, std::size_t size);

// PNG's CRC-32 (ISO/IEC 15948, annex D).
std::uint32_t png_crc32(const unsigned char* data, std::size_t size);

}  // namespace impossible::image
