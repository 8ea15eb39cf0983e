#include "glb_container.hpp"

#include <cstdio>

namespace impossible::tools {

void append_u32(std::vector<unsigned char>& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<unsigned char>(v >> (8 * i)));
}

std::vector<unsigned char> glb_of(const std::string& json, const std::vector<unsigned char>& bin) {
    std::vector<unsigned char> glb;
    const auto total = static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size());
    append_u32(glb, 0x46546C67);  // "glTF"
    append_u32(glb, 2);
    append_u32(glb, total);
    append_u32(glb, static_cast<std::uint32_t>(json.size()));
    append_u32(glb, 0x4E4F534A);  // "JSON"
    glb.insert(glb.end(), json.begin(), json.end());
    append_u32(glb, static_cast<std::uint32_t>(bin.size()));
    append_u32(glb, 0x004E4942);  // "BIN\0"
    glb.insert(glb.end(), bin.begin(), bin.end());
    return glb;
}

std::string json_number(float v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", static_cast<double>(v));
    return buffer;
}

}  // namespace impossible::tools
