#include "image/decode.hpp"

#include <climits>
#include <cstring>
#include <memory>

#include <stb_image.h>

#include "base/user_text.hpp"

namespace impossible::image {

namespace {

// stb_image's reason can quote bytes of the file (an unknown PNG chunk's
// four type bytes), so it is made printable before it joins a message.
std::string stb_reason() {
    const char* reason = stbi_failure_reason();
    return reason != nullptr && *reason != '\0' ? printable(reason) : "unknown reason";
}

// stbi_load_from_memory into Pixels of `want` channels (1, 3 or 4); the
// error is stb_image's reason.
Result<Pixels> stb_decode(const unsigned char* bytes, std::size_t size, int want) {
    if (size > static_cast<std::size_t>(INT_MAX)) return Error{"is too large to decode"};
    int width = 0, height = 0, channels = 0;
    const std::unique_ptr<unsigned char, void (*)(void*)> decoded(
        stbi_load_from_memory(bytes, static_cast<int>(size), &width, &height, &channels, want), &stbi_image_free);
    if (decoded == nullptr) return Error{stb_reason()};
    Pixels out;
    out.width = width;
    out.height = height;
    out.channels = want;
    out.data.assign(decoded.get(), decoded.get() + out.texels() * static_cast<std::size_t>(want));
    return out;
}

}  // namespace

ImageFormat sniff_image(const unsigned char* bytes, std::size_t size) {
    static const unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    if (size >= sizeof png && std::memcmp(bytes, png, sizeof png) == 0) return ImageFormat::Png;
    if (size >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF) return ImageFormat::Jpeg;
    return ImageFormat::Other;
}

Result<ImageSize> image_size(const unsigned char* bytes, std::size_t size, int max_side) {
    if (sniff_image(bytes, size) == ImageFormat::Other) return Error{"is neither PNG nor JPEG data"};
    if (size > static_cast<std::size_t>(INT_MAX)) return Error{"is too large to decode"};
    ImageSize out;
    int channels = 0;
    if (stbi_info_from_memory(bytes, static_cast<int>(size), &out.width, &out.height, &channels) == 0) {
        return Error{"could not be decoded (" + stb_reason() + ")"};
    }
    if (out.width < 1 || out.height < 1) return Error{"could not be decoded (it has no pixels)"};
    if (out.width > max_side || out.height > max_side) {
        return Error{"is " + std::to_string(out.width) + " x " + std::to_string(out.height) + " pixels; the limit is " +
                     std::to_string(max_side) + " pixels on a side"};
    }
    return out;
}

Result<Pixels> decode_image(const unsigned char* bytes, std::size_t size, int max_side) {
    const Result<ImageSize> header = image_size(bytes, size, max_side);
    if (!header) return header;
    // stbi_load reduces 16-bit PNG channels to 8 bits and expands grey, grey
    // with alpha and RGB to RGBA (alpha 255).
    Result<Pixels> pixels = stb_decode(bytes, size, 4);
    if (!pixels) return Error{"could not be decoded (" + pixels.error() + ")"};
    if (pixels->width != header->width || pixels->height != header->height) {
        return Error{"could not be decoded (its size changed while decoding)"};
    }
    return pixels;
}

Result<Pixels> decode_grey_or_rgb(const unsigned char* bytes, std::size_t size) {
    if (size > static_cast<std::size_t>(INT_MAX)) return Error{"is too large to decode"};
    int w = 0, h = 0, n = 0;
    if (!stbi_info_from_memory(bytes, static_cast<int>(size), &w, &h, &n)) return Error{stb_reason()};
    return stb_decode(bytes, size, (n == 1 || n == 2) ? 1 : 3);
}

}  // namespace impossible::image
