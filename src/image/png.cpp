#include "image/png.hpp"

#include "base/file_io.hpp"
#include "base/output_file.hpp"
#include "image/decode.hpp"
#include "image/png_check.hpp"

#include <stb_image_write.h>

namespace impossible::image {
namespace {

void append_bytes(void* context, void* data, int size) {
    auto* out = static_cast<std::string*>(context);
    out->append(static_cast<const char*>(data), static_cast<size_t>(size));
}

// A PNG file is at most this long (an uncompressed 2 × 8192² RGB frame is
// 384 MiB; PNGs of such frames are far smaller).
constexpr std::size_t kMaxPngBytes = 512u << 20;

}  // namespace

Result<std::string> encode_png(int width, int height, int channels, const std::vector<std::uint8_t>& pixels) {
    if (width <= 0 || height <= 0 || (channels != 1 && channels != 3) ||
        pixels.size() != static_cast<size_t>(width) * height * channels)
        return Error{"internal error: bad image size"};
    std::string encoded;
    if (!stbi_write_png_to_func(append_bytes, &encoded, width, height, channels, pixels.data(), width * channels))
        return Error{"cannot encode PNG"};
    return encoded;
}

Result<void> write_png(const std::string& path, int width, int height, int channels,
                       const std::vector<std::uint8_t>& pixels) {
    Result<std::string> encoded = encode_png(width, height, channels, pixels);
    if (!encoded) return Error{path + ": " + encoded.error()};
    return write_output_file(path, *encoded);
}

Result<Pixels> read_png(const std::string& path) {
    const Result<std::vector<unsigned char>> bytes = read_file_bytes(path, kMaxPngBytes, false);
    if (!bytes) return Error{path + ": " + bytes.error()};
    const Result<PngHeader> header = check_png(*bytes);
    if (!header) return Error{path + ": " + header.error()};
    Result<Pixels> image = decode_grey_or_rgb(bytes->data(), bytes->size());
    if (!image) return Error{path + ": cannot decode the PNG (" + image.error() + ")"};
    image->bit_depth = header->bit_depth;
    return image;
}

}  // namespace impossible::image
