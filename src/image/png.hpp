// PNG files in and out (stb_image_write / stb_image from Debian's libstb).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/result.hpp"

namespace impossible::image {

// Writes an 8-bit PNG with 1 (grey) or 3 (RGB) channels, rows from the top.
// The file appears whole or not at all: it is written under a temporary name
// in the same directory and renamed.
Result<void> write_png(const std::string& path, int width, int height, int channels,
                      const std::vector<std::uint8_t>& pixels);

struct PngImage {
    int width = 0;
    int height = 0;
    int channels = 0;
    std::vector<std::uint8_t> pixels;
};

// Reads a PNG, keeping it as 1 or 3 channels (grey stays grey).
Result<PngImage> read_png(const std::string& path);

}  // namespace impossible::image
