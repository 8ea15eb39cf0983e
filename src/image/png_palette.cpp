#include "image/png_palette.hpp"

#include <array>
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "base/user_text.hpp"
#include "image/png_check.hpp"
#include "image/stb_load.hpp"

namespace impossible::image {
namespace {

std::uint32_t palette_be32(const unsigned char* p) {
    return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) | p[3];
}

void palette_append_be32(std::vector<unsigned char>& out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<unsigned char>(v >> shift));
}

// What decoding a palette PNG needs from its chunks.
struct PaletteChunks {
    int bit_depth = 0;
    int colour_type = -1;
    int plte_chunks = 0;
    int entries = 0;                            // of the PLTE chunk; 0 when its length is not 3 to 768 by 3
    std::size_t plte_at = 0, plte_end = 0;      // where the PLTE chunk lies, length to CRC
    std::array<unsigned char, 256 * 4> rgba{};  // the PLTE's colours, alpha from tRNS (255 without)
};

// Reads IHDR, PLTE and tRNS, from the first chunk to IEND or a chunk that
// runs past the end (check_png_chunks refuses that first). A tRNS before
// PLTE is left to stb_image, which refuses it.
Result<PaletteChunks> read_palette_chunks(const unsigned char* bytes, std::size_t size) {
    PaletteChunks out;
    for (std::size_t at = 8; size >= at && size - at >= 12;) {
        const std::uint32_t length = palette_be32(bytes + at);
        if (length > size - at - 12) break;
        const std::string type(reinterpret_cast<const char*>(bytes + at + 4), 4);
        const unsigned char* data = bytes + at + 8;
        if (at == 8) {
            if (type != "IHDR" || length != 13) break;
            out.bit_depth = data[8];
            out.colour_type = data[9];
            if (out.colour_type != 3) break;
        } else if (type == "PLTE") {
            if (++out.plte_chunks > 1) return Error{"it has more than one PLTE chunk"};
            out.entries = length > 0 && length % 3 == 0 && length <= 768 ? static_cast<int>(length / 3) : 0;
            for (int i = 0; i < out.entries; ++i) {
                std::memcpy(out.rgba.data() + 4 * i, data + 3 * i, 3);
                out.rgba[static_cast<std::size_t>(4 * i + 3)] = 255;
            }
            out.plte_at = at;
            out.plte_end = at + 12 + length;
        } else if (type == "tRNS" && out.entries > 0) {
            if (length > static_cast<std::uint32_t>(out.entries)) {
                return Error{"its tRNS chunk has " + std::to_string(length) + " entries, more than the " +
                             std::to_string(out.entries) + " of its PLTE chunk"};
            }
            for (std::uint32_t i = 0; i < length; ++i) out.rgba[4 * i + 3] = data[i];
        } else if (type == "IEND") {
            break;
        }
        at += 12 + std::size_t(length);
    }
    return out;
}

// The PNG with its PLTE replaced by 256 entries, entry i being (i, i, i).
std::vector<unsigned char> with_identity_palette(const unsigned char* bytes, std::size_t size,
                                                 const PaletteChunks& chunks) {
    std::vector<unsigned char> png(bytes, bytes + chunks.plte_at);
    png.reserve(size + 768);
    palette_append_be32(png, 768);
    const std::size_t type_at = png.size();
    png.insert(png.end(), {'P', 'L', 'T', 'E'});
    for (int i = 0; i < 256; ++i) png.insert(png.end(), 3, static_cast<unsigned char>(i));
    palette_append_be32(png, png_crc32(png.data() + type_at, 4 + 768));
    png.insert(png.end(), bytes + chunks.plte_end, bytes + size);
    return png;
}

// RGBA pixels to `want` channels as stb_image converts them (grey is its
// integer luma).
void palette_to_channels(Pixels& pixels, int want) {
    if (want == 4) return;
    const std::size_t n = pixels.texels();
    std::uint8_t* d = pixels.data.data();
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint8_t* p = d + 4 * i;
        const auto grey = static_cast<std::uint8_t>((p[0] * 77 + p[1] * 150 + p[2] * 29) >> 8);
        const std::uint8_t out[4] = {want >= 3 ? p[0] : grey, want == 2 ? p[3] : p[1], p[2], p[3]};
        std::memmove(d + static_cast<std::size_t>(want) * i, out, static_cast<std::size_t>(want));
    }
    pixels.data.resize(n * static_cast<std::size_t>(want));
    pixels.channels = want;
}

}  // namespace

std::optional<Result<Pixels>> decode_short_palette(const unsigned char* bytes, std::size_t size, int want) {
    const Result<PaletteChunks> chunks = read_palette_chunks(bytes, size);
    if (!chunks) return Result<Pixels>(Error{chunks.error()});
    const int depth = chunks->bit_depth;
    if (chunks->colour_type != 3 || (depth != 1 && depth != 2 && depth != 4 && depth != 8) || chunks->entries == 0 ||
        chunks->entries >= (1 << depth)) {
        return std::nullopt;
    }
    const std::vector<unsigned char> png = with_identity_palette(bytes, size, *chunks);
    Result<Pixels> pixels = stb::load(png.data(), png.size(), 4);
    if (!pixels) return std::optional<Result<Pixels>>(std::move(pixels));
    // Each index to its colour, the first index past the PLTE noted.
    const std::size_t n = pixels->texels();
    const int entries = chunks->entries;
    std::array<std::uint32_t, 256> colours{};
    std::memcpy(colours.data(), chunks->rgba.data(), sizeof colours);
    std::uint8_t* d = pixels->data.data();
    std::size_t first_past = n;
    int past_index = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint8_t index = d[4 * i];
        if (index >= entries && first_past == n) {
            first_past = i;
            past_index = index;
        }
        std::memcpy(d + 4 * i, &colours[index], 4);
    }
    if (first_past < n) {
        const auto width = static_cast<std::size_t>(pixels->width);
        return Result<Pixels>(
            Error{"pixel (" + std::to_string(first_past % width) + ", " + std::to_string(first_past / width) +
                  ") has the palette index " + std::to_string(past_index) + ", past the " +
                  count_of(static_cast<std::size_t>(entries), "entry", "entries") + " of its PLTE chunk"});
    }
    palette_to_channels(*pixels, want);
    return std::optional<Result<Pixels>>(std::move(pixels));
}

}  // namespace impossible::image
