// The pieces every .glb writer here shares: little-endian words, and the GLB
// container (12-byte header, JSON chunk, BIN chunk) around a model's JSON and
// binary buffer.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace impossible::tools {

void append_u32(std::vector<unsigned char>& out, std::uint32_t v);

// `json` must already be padded with spaces to a multiple of 4 bytes, and
// `bin` with zeros.
std::vector<unsigned char> glb_of(const std::string& json, const std::vector<unsigned char>& bin);

// A float as glTF JSON text that reads back to the same float.
std::string json_number(float v);

}  // namespace impossible::tools
