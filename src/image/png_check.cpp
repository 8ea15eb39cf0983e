// PNG chunk layout and CRC from the PNG specification (ISO/IEC 15948,
// sections 5.3 and D: CRC-32, polynomial 0xEDB88320).
#include "image/png_check.hpp"

#include <array>
#include <string>

namespace impossible::image {
namespace {

std::uint32_t crc32(const unsigned char* data, std::size_t size) {
    static const std::array<std::uint32_t, 256> table = [] {
        std::array<std::uint32_t, 256> t{};
        for (std::uint32_t n = 0; n < 256; ++n) {
            std::uint32_t c = n;
            for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
            t[n] = c;
        }
        return t;
    }();
    std::uint32_t c = 0xFFFFFFFFu;
    for (std::size_t i = 0; i < size; ++i) c = table[(c ^ data[i]) & 0xFF] ^ (c >> 8);
    return c ^ 0xFFFFFFFFu;
}

std::uint32_t be32(const unsigned char* p) {
    return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) | p[3];
}

bool is_letter(unsigned char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

}  // namespace

Result<PngHeader> check_png(const std::vector<unsigned char>& bytes) {
    static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    if (bytes.size() < 8 || !std::equal(kSignature, kSignature + 8, bytes.begin()))
        return Error{"is not a PNG file (it does not start with the PNG signature)"};
    PngHeader header;
    std::size_t at = 8;
    bool first = true;
    for (;;) {
        if (bytes.size() - at < 12) return Error{"is truncated (it ends before its last chunk, IEND)"};
        const unsigned char* chunk = bytes.data() + at;
        const std::uint32_t length = be32(chunk);
        if (!(is_letter(chunk[4]) && is_letter(chunk[5]) && is_letter(chunk[6]) && is_letter(chunk[7])))
            return Error{"has a damaged chunk at byte " + std::to_string(at) + " (its type is not four letters)"};
        const std::string type(reinterpret_cast<const char*>(chunk + 4), 4);
        if (length > bytes.size() - at - 12)
            return Error{"is truncated (chunk " + type + " runs past the end of the file)"};
        if (crc32(chunk + 4, 4 + std::size_t(length)) != be32(chunk + 8 + length))
            return Error{"has a damaged chunk " + type + " (its CRC does not match its data)"};
        if (first) {
            if (type != "IHDR" || length != 13) return Error{"is damaged (it does not start with an IHDR chunk)"};
            header.width = be32(chunk + 8);
            header.height = be32(chunk + 12);
            header.bit_depth = chunk[16];
            header.colour_type = chunk[17];
            if (header.width == 0 || header.height == 0) return Error{"is damaged (it has no pixels)"};
            if (std::uint64_t(header.width) * header.height > kMaxPngPixels)
                return Error{"is too large (" + std::to_string(header.width) + "x" + std::to_string(header.height) +
                             " pixels; the limit is " + std::to_string(kMaxPngPixels) + " pixels)"};
            first = false;
        }
        at += 12 + std::size_t(length);
        if (type == "IEND") return header;
    }
}

}  // namespace impossible::image
