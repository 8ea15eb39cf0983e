// PNG chunk layout and CRC from the PNG specification (ISO/IEC 15948,
// sections 5.3 and D: CRC-32, polynomial 0xEDB88320).
#include "image/png_check.hpp"

#include <algorithm>
#include <array>
#include <string>

namespace impossible::image {
namespace {

const unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};

std::uint32_t be32(const unsigned char* p) {
    return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) | p[3];
}

bool is_letter(unsigned char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

// The chunk at `at`: whole, typed by four letters, its CRC right; its type
// in `type`, the offset past it in `next`. Empty when sound, else the fault.
std::string chunk_fault(const unsigned char* bytes, std::size_t size, std::size_t at, std::string& type,
                        std::size_t& next) {
    if (size - at < 12) return "is truncated (it ends before its last chunk, IEND)";
    const unsigned char* chunk = bytes + at;
    const std::uint32_t length = be32(chunk);
    if (!(is_letter(chunk[4]) && is_letter(chunk[5]) && is_letter(chunk[6]) && is_letter(chunk[7])))
        return "has a damaged chunk at byte " + std::to_string(at) + " (its type is not four letters)";
    type.assign(reinterpret_cast<const char*>(chunk + 4), 4);
    if (length > size - at - 12) return "is truncated (chunk " + type + " runs past the end of the file)";
    if (png_crc32(chunk + 4, 4 + std::size_t(length)) != be32(chunk + 8 + length))
        return "has a damaged chunk " + type + " (its CRC does not match its data)";
    next = at + 12 + std::size_t(length);
    return {};
}

}  // namespace

std::uint32_t png_crc32(const unsigned char* data, std::size_t size) {
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

Result<PngHeader> png_header(const unsigned char* bytes, std::size_t size) {
    if (size < 8 || !std::equal(kPngSignature, kPngSignature + 8, bytes))
        return Error{"is not a PNG file (it does not start with the PNG signature)"};
    std::string type;
    std::size_t next = 0;
    if (std::string fault = chunk_fault(bytes, size, 8, type, next); !fault.empty()) return Error{fault};
    if (type != "IHDR" || be32(bytes + 8) != 13) return Error{"is damaged (it does not start with an IHDR chunk)"};
    PngHeader header;
    header.width = be32(bytes + 16);
    header.height = be32(bytes + 20);
    header.bit_depth = bytes[24];
    header.colour_type = bytes[25];
    if (header.width == 0 || header.height == 0) return Error{"is damaged (it has no pixels)"};
    return header;
}

Result<void> check_png_chunks(const unsigned char* bytes, std::size_t size) {
    std::size_t at = 8;
    std::string type;
    while (type != "IEND") {
        if (std::string fault = chunk_fault(bytes, size, at, type, at); !fault.empty()) return Error{fault};
    }
    return {};
}

Result<PngHeader> check_png(const std::vector<unsigned char>& bytes) {
    Result<PngHeader> header = png_header(bytes.data(), bytes.size());
    if (!header) return header;
    if (std::uint64_t(header->width) * header->height > kMaxPngPixels)
        return Error{"is too large (" + std::to_string(header->width) + "x" + std::to_string(header->height) +
                     " pixels; the limit is " + std::to_string(kMaxPngPixels) + " pixels)"};
    if (Result<void> chunks = check_png_chunks(bytes.data(), bytes.size()); !chunks) return Error{chunks.error()};
    return header;
}

}  // namespace impossible::image
