#include "image/decode.hpp"

#include <climits>
#include <cstdint>
#include <cstring>
#include <utility>

#include "image/jpeg_check.hpp"
#include "image/png_check.hpp"
#include "image/png_palette.hpp"
#include "image/stb_load.hpp"

namespace impossible::image {

namespace {

std::string cannot_decode(ImageFormat format, const std::string& reason) {
    return std::string("could not be decoded as ") + (format == ImageFormat::Png ? "PNG: " : "JPEG: ") + reason;
}

// Pixels of `want` channels from PNG or JPEG data whose structure was
// checked; the error is the reason alone.
Result<Pixels> decode_pixels(ImageFormat format, const unsigned char* bytes, std::size_t size, int want) {
    if (format == ImageFormat::Png) {
        if (std::optional<Result<Pixels>> palette = decode_short_palette(bytes, size, want)) return std::move(*palette);
    }
    return stb::load(bytes, size, want);
}

}  // namespace

ImageFormat sniff_image(const unsigned char* bytes, std::size_t size) {
    static const unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    if (size >= sizeof png && std::memcmp(bytes, png, sizeof png) == 0) return ImageFormat::Png;
    if (size >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF) return ImageFormat::Jpeg;
    return ImageFormat::Other;
}

Result<ImageSize> image_size(const unsigned char* bytes, std::size_t size, int max_side) {
    const ImageFormat format = sniff_image(bytes, size);
    if (format == ImageFormat::Other) return Error{"is neither PNG nor JPEG data"};
    std::uint64_t width = 0, height = 0;
    if (format == ImageFormat::Png) {
        const Result<PngHeader> header = png_header(bytes, size);
        if (!header) return Error{cannot_decode(format, "it " + header.error())};
        width = header->width;
        height = header->height;
    } else {
        const Result<JpegFrame> frame = read_jpeg_markers(bytes, size, false);
        if (!frame) return Error{cannot_decode(format, "it " + frame.error())};
        width = static_cast<std::uint64_t>(frame->width);
        height = static_cast<std::uint64_t>(frame->height);
        if (width == 0 || height == 0) {
            return Error{cannot_decode(format, "it has no pixels (its frame header says " + std::to_string(width) +
                                                   " x " + std::to_string(height) + ")")};
        }
    }
    const auto limit = static_cast<std::uint64_t>(max_side);
    if (width > limit || height > limit) {
        return Error{"is " + std::to_string(width) + " x " + std::to_string(height) + " pixels; the limit is " +
                     std::to_string(max_side) + " pixels on a side"};
    }
    return ImageSize{static_cast<int>(width), static_cast<int>(height)};
}

Result<Pixels> decode_image(const unsigned char* bytes, std::size_t size, int max_side) {
    const Result<ImageSize> header = image_size(bytes, size, max_side);
    if (!header) return header;
    const ImageFormat format = sniff_image(bytes, size);
    if (format == ImageFormat::Png) {
        if (Result<void> chunks = check_png_chunks(bytes, size); !chunks) {
            return Error{cannot_decode(format, "it " + chunks.error())};
        }
    } else if (const Result<JpegFrame> markers = read_jpeg_markers(bytes, size, true); !markers) {
        return Error{cannot_decode(format, "it " + markers.error())};
    }
    // stb_image reduces 16-bit PNG channels to 8 bits and expands grey, grey
    // with alpha and RGB to RGBA (alpha 255).
    Result<Pixels> pixels = decode_pixels(format, bytes, size, 4);
    if (!pixels) return Error{cannot_decode(format, pixels.error())};
    if (pixels->width != header->width || pixels->height != header->height) {
        return Error{cannot_decode(format, "its size changed while decoding")};
    }
    return pixels;
}

Result<Pixels> decode_grey_or_rgb(const unsigned char* bytes, std::size_t size) {
    if (sniff_image(bytes, size) != ImageFormat::Png) return Error{"it is not PNG data"};
    const Result<int> channels = stb::channels(bytes, size);
    if (!channels) return Error{channels.error()};
    return decode_pixels(ImageFormat::Png, bytes, size, (*channels == 1 || *channels == 2) ? 1 : 3);
}

}  // namespace impossible::image
