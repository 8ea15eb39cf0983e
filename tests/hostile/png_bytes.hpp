// Hand-made PNG files for attacks on `compare`: any bit depth and colour
// type, stored (uncompressed) deflate blocks, correct CRCs unless damaged
// afterwards.
#pragma once

#include <cstdint>
#include <string>

namespace impossible::hostile {

inline std::uint32_t png_crc(const std::string& bytes) {
    std::uint32_t c = 0xFFFFFFFFu;
    for (unsigned char b : bytes) {
        c ^= b;
        for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    }
    return c ^ 0xFFFFFFFFu;
}

inline std::string be32(std::uint32_t v) { return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)}; }

inline std::string png_chunk(const std::string& type, const std::string& data) {
    return be32(static_cast<std::uint32_t>(data.size())) + type + data + be32(png_crc(type + data));
}

// A PNG of `rows` (each with its filter byte) as one stored deflate block
// (at most 65535 bytes).
inline std::string png_file(std::uint32_t width, std::uint32_t height, int bit_depth, int colour_type,
                            const std::string& rows) {
    std::string ihdr = be32(width) + be32(height);
    ihdr += {char(bit_depth), char(colour_type), 0, 0, 0};
    std::uint32_t a = 1, b = 0;
    for (unsigned char c : rows) {
        a = (a + c) % 65521;
        b = (b + a) % 65521;
    }
    const auto n = static_cast<std::uint16_t>(rows.size());
    std::string z = {0x78, 0x01, 0x01, char(n & 0xFF), char(n >> 8), char(~n & 0xFF), char((~n >> 8) & 0xFF)};
    z += rows + be32((b << 16) | a);
    return std::string("\x89PNG\r\n\x1a\n", 8) + png_chunk("IHDR", ihdr) + png_chunk("IDAT", z) + png_chunk("IEND", "");
}

}  // namespace impossible::hostile
