#include "layout/image_decode.hpp"

#include <climits>
#include <cstring>
#include <memory>

#include <stb_image.h>

#include "layout/limits.hpp"

namespace impossible::layout::detail {

namespace {

std::string stb_reason() {
    const char* reason = stbi_failure_reason();
    return reason != nullptr && *reason != '\0' ? reason : "unknown reason";
}

}  // namespace

ImageFormat sniff_image(const unsigned char* bytes, std::size_t size) {
    static const unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    if (size >= sizeof png && std::memcmp(bytes, png, sizeof png) == 0) return ImageFormat::Png;
    if (size >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF) return ImageFormat::Jpeg;
    return ImageFormat::Other;
}

Result<ImageSize> image_size(const unsigned char* bytes, std::size_t size) {
    if (sniff_image(bytes, size) == ImageFormat::Other) return Error{"is neither PNG nor JPEG data"};
    if (size > static_cast<std::size_t>(INT_MAX)) return Error{"is too large to decode"};
    ImageSize out;
    int channels = 0;
    if (stbi_info_from_memory(bytes, static_cast<int>(size), &out.width, &out.height, &channels) == 0) {
        return Error{"could not be decoded (" + stb_reason() + ")"};
    }
    if (out.width < 1 || out.height < 1) return Error{"could not be decoded (it has no pixels)"};
    if (out.width > limits::kMaxImageSide || out.height > limits::kMaxImageSide) {
        return Error{"is " + std::to_string(out.width) + " x " + std::to_string(out.height) +
                     " pixels; the limit is " + std::to_string(limits::kMaxImageSide) + " pixels on a side"};
    }
    return out;
}

Result<Image> decode_image(const unsigned char* bytes, std::size_t size) {
    const Result<ImageSize> header = image_size(bytes, size);
    if (!header) return Error{header.error()};
    int width = 0, height = 0, channels = 0;
    // stbi_load reduces 16-bit PNG channels to 8 bits and expands grey, grey
    // with alpha and RGB to RGBA (alpha 255).
    const std::unique_ptr<unsigned char, void (*)(void*)> pixels(
        stbi_load_from_memory(bytes, static_cast<int>(size), &width, &height, &channels, 4), &stbi_image_free);
    if (pixels == nullptr) return Error{"could not be decoded (" + stb_reason() + ")"};
    if (width != header->width || height != header->height) {
        return Error{"could not be decoded (its size changed while decoding)"};
    }
    Image image;
    image.width = width;
    image.height = height;
    image.rgba.assign(pixels.get(), pixels.get() + header->texels() * 4);
    return image;
}

}  // namespace impossible::layout::detail
