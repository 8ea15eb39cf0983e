// stb_image, compiled here from the header of Debian's libstb-dev for PNG and
// JPEG only (STB_IMAGE_STATIC: no symbol of it leaves this file), instead of
// linking libstb's compiled copy, so that its allocations can be zeroed.
// Where stb_image's decoder leaves pixels unwritten (the blocks after a
// missing restart marker of a JPEG scan, a JPEG component no scan covers),
// they are then 0 instead of whatever the heap held before, and the same
// file decodes to the same pixels every time. (A palette index past the PLTE
// chunk reads stb_image's stack, not its heap: png_palette.cpp.)
#include <climits>
#include <cstdlib>
#include <cstring>
#include <memory>

#include "base/user_text.hpp"
#include "image/stb_load.hpp"

namespace {

void* stbi_zeroed_malloc(std::size_t size) { return std::calloc(1, size == 0 ? 1 : size); }

void* stbi_zeroed_realloc(void* p, std::size_t old_size, std::size_t new_size) {
    auto* grown = static_cast<unsigned char*>(std::realloc(p, new_size == 0 ? 1 : new_size));
    if (grown != nullptr && new_size > old_size) std::memset(grown + old_size, 0, new_size - old_size);
    return grown;
}

}  // namespace

#define STBI_MALLOC(size) stbi_zeroed_malloc(size)
#define STBI_REALLOC_SIZED(p, old_size, new_size) stbi_zeroed_realloc(p, old_size, new_size)
#define STBI_FREE(p) std::free(p)
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_NO_STDIO
#define STBI_NO_LINEAR
#include <stb_image.h>

namespace impossible::image::stb {

namespace {

// stb_image's reason for the last failure; its PNG test's "bad png sig",
// left before it decodes JPEG data, is none.
std::string stb_failure_reason(const unsigned char* bytes, std::size_t size) {
    const char* reason = stbi__g_failure_reason;
    if (reason != nullptr && *reason != '\0' && std::strcmp(reason, "bad png sig") != 0) return printable(reason);
    return size >= 1 && bytes[0] == 0x89 ? "its compressed image data is corrupt" : "its image data is corrupt";
}

}  // namespace

Result<Pixels> load(const unsigned char* bytes, std::size_t size, int want) {
    if (size > static_cast<std::size_t>(INT_MAX)) return Error{"it is too large to decode"};
    stbi__g_failure_reason = nullptr;
    int width = 0, height = 0, channels = 0;
    const std::unique_ptr<unsigned char, void (*)(void*)> decoded(
        stbi_load_from_memory(bytes, static_cast<int>(size), &width, &height, &channels, want), &stbi_image_free);
    if (decoded == nullptr) return Error{stb_failure_reason(bytes, size)};
    Pixels out;
    out.width = width;
    out.height = height;
    out.channels = want;
    out.data.assign(decoded.get(), decoded.get() + out.texels() * static_cast<std::size_t>(want));
    return out;
}

Result<int> channels(const unsigned char* bytes, std::size_t size) {
    if (size > static_cast<std::size_t>(INT_MAX)) return Error{"it is too large to decode"};
    stbi__g_failure_reason = nullptr;
    int width = 0, height = 0, n = 0;
    if (stbi_info_from_memory(bytes, static_cast<int>(size), &width, &height, &n) == 0) {
        return Error{stb_failure_reason(bytes, size)};
    }
    return n;
}

}  // namespace impossible::image::stb
