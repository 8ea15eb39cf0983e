// stb_image's decoder as this module uses it (stb_image_impl.cpp): PNG and
// JPEG only, every allocation zeroed.
#pragma once

#include <cstddef>

#include "base/result.hpp"
#include "image/pixels.hpp"

namespace impossible::image::stb {

// stbi_load_from_memory to `want` channels (1 to 4). The error is stb_image's
// reason, printable ("bad zlib header"); where its decoder gives none,
// "its compressed image data is corrupt" for PNG data and "its image data is
// corrupt" for JPEG data.
Result<Pixels> load(const unsigned char* bytes, std::size_t size, int want);

// The channels the image's header declares (1 to 4), by stbi_info_from_memory.
Result<int> channels(const unsigned char* bytes, std::size_t size);

}  // namespace impossible::image::stb
