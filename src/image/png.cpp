#include "image/png.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include <stb_image.h>
#include <stb_image_write.h>

namespace impossible::image {
namespace {

void append_bytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<unsigned char>*>(context);
    const auto* bytes = static_cast<const unsigned char*>(data);
    out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

Result<void> write_png(const std::string& path, int width, int height, int channels,
                      const std::vector<std::uint8_t>& pixels) {
    if (width <= 0 || height <= 0 || (channels != 1 && channels != 3) ||
        pixels.size() != static_cast<size_t>(width) * height * channels)
        return Error{path + ": internal error: bad image size"};
    std::vector<unsigned char> encoded;
    if (!stbi_write_png_to_func(append_bytes, &encoded, width, height, channels, pixels.data(),
                                width * channels))
        return Error{path + ": cannot encode PNG"};

    const std::string temp = path + ".tmp-" + std::to_string(::getpid());
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        if (!out) return Error{path + ": cannot write: " + std::strerror(errno)};
        out.write(reinterpret_cast<const char*>(encoded.data()), static_cast<std::streamsize>(encoded.size()));
        out.close();
        if (!out) {
            std::error_code ignored;
            std::filesystem::remove(temp, ignored);
            return Error{path + ": cannot write: " + std::strerror(errno)};
        }
    }
    std::error_code ec;
    std::filesystem::rename(temp, path, ec);
    if (ec) {
        std::error_code ignored;
        std::filesystem::remove(temp, ignored);
        return Error{path + ": cannot write: " + ec.message()};
    }
    return {};
}

Result<PngImage> read_png(const std::string& path) {
    PngImage image;
    int w = 0, h = 0, n = 0;
    if (!stbi_info(path.c_str(), &w, &h, &n)) {
        return Error{path + ": cannot read PNG: " + (stbi_failure_reason() ? stbi_failure_reason() : "unknown")};
    }
    const int want = (n == 1 || n == 2) ? 1 : 3;
    unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, want);
    if (!data) {
        return Error{path + ": cannot read PNG: " + (stbi_failure_reason() ? stbi_failure_reason() : "unknown")};
    }
    image.width = w;
    image.height = h;
    image.channels = want;
    image.pixels.assign(data, data + static_cast<size_t>(w) * h * want);
    stbi_image_free(data);
    return image;
}

}  // namespace impossible::image
