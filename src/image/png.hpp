// PNG files in and out (stb_image_write / stb_image from Debian's libstb).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/result.hpp"
#include "image/pixels.hpp"

namespace impossible::image {

// Encodes an 8-bit PNG with 1 (grey) or 3 (RGB) channels, rows from the top.
Result<std::string> encode_png(int width, int height, int channels, const std::vector<std::uint8_t>& pixels);

// Encodes and writes one PNG through base/output_file.hpp: whole or not at
// all, never replacing a link or a device. Commands with several outputs
// encode with encode_png and write them together (cli/output_files.hpp).
Result<void> write_png(const std::string& path, int width, int height, int channels,
                       const std::vector<std::uint8_t>& pixels);

// Reads a PNG, keeping it as 1 or 3 channels (grey stays grey), with the
// file's bit depth. The file is
// checked first (png_check.hpp: CRCs, truncation, at most kMaxPngPixels);
// errors are "PATH: reason" in words.
Result<Pixels> read_png(const std::string& path);

}  // namespace impossible::image
