// Writes small glTF models for tests: a .gltf document with its buffer
// embedded as a data URI, or a .glb (JSON chunk and binary chunk).
#pragma once

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace layout_test {
namespace {

// One triangle's positions (x, y, z each), for the smallest models.
const std::vector<float> kTriangle = {0, 0, 0, 1, 0, 0, 0, 1, 0};

using nlohmann::json;

std::string base64(const std::vector<unsigned char>& data) {
    static const char table[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < data.size(); i += 3) {
        const unsigned v = (unsigned(data[i]) << 16) | (i + 1 < data.size() ? unsigned(data[i + 1]) << 8 : 0) |
                           (i + 2 < data.size() ? unsigned(data[i + 2]) : 0);
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += i + 1 < data.size() ? table[(v >> 6) & 63] : '=';
        out += i + 2 < data.size() ? table[v & 63] : '=';
    }
    return out;
}

// A .gltf document with its buffer embedded as a data URI.
struct GltfWriter {
    json doc = {{"asset", {{"version", "2.0"}}},
                {"bufferViews", json::array()},
                {"accessors", json::array()},
                {"meshes", json::array()},
                {"nodes", json::array()}};
    std::vector<unsigned char> bin;

    int view(const void* data, std::size_t bytes) {
        while (bin.size() % 4 != 0) bin.push_back(0);
        const std::size_t offset = bin.size();
        bin.resize(offset + bytes);
        std::memcpy(bin.data() + offset, data, bytes);
        doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}});
        return int(doc["bufferViews"].size()) - 1;
    }
    int vec3(const std::vector<float>& v, int component_type = 5126) {
        const int bv = view(v.data(), v.size() * sizeof(float));
        doc["accessors"].push_back(
            {{"bufferView", bv}, {"componentType", component_type}, {"count", v.size() / 3}, {"type", "VEC3"}});
        return int(doc["accessors"].size()) - 1;
    }
    template <class T>
    int indices(const std::vector<T>& v) {
        const int bv = view(v.data(), v.size() * sizeof(T));
        const int type = sizeof(T) == 1 ? 5121 : sizeof(T) == 2 ? 5123 : 5125;
        doc["accessors"].push_back(
            {{"bufferView", bv}, {"componentType", type}, {"count", v.size()}, {"type", "SCALAR"}});
        return int(doc["accessors"].size()) - 1;
    }
    // A mesh with one primitive; returns the mesh index.
    int mesh(json primitive) {
        doc["meshes"].push_back({{"primitives", json::array({std::move(primitive)})}});
        return int(doc["meshes"].size()) - 1;
    }
    int node(json node) {
        doc["nodes"].push_back(std::move(node));
        return int(doc["nodes"].size()) - 1;
    }
    void write(const std::string& path) {
        doc["buffers"] =
            json::array({{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}});
        if (!doc.contains("scenes")) {
            json roots = json::array();
            for (std::size_t i = 0; i < doc["nodes"].size(); ++i) roots.push_back(i);
            doc["scenes"] = json::array({{{"nodes", roots}}});
            doc["scene"] = 0;
        }
        std::ofstream(path, std::ios::binary) << doc.dump(1);
    }
};

// A .glb file of `json_text` and `bin` (padded as the spec asks).
inline void write_glb(const std::string& path, std::string json_text, std::vector<unsigned char> bin) {
    while (json_text.size() % 4 != 0) json_text += ' ';
    while (bin.size() % 4 != 0) bin.push_back(0);
    std::vector<unsigned char> out;
    const auto u32 = [&](std::uint32_t v) {
        for (int i = 0; i < 4; ++i) out.push_back(static_cast<unsigned char>(v >> (8 * i)));
    };
    const std::size_t total = 12 + 8 + json_text.size() + (bin.empty() ? 0 : 8 + bin.size());
    out.insert(out.end(), {'g', 'l', 'T', 'F'});
    u32(2);
    u32(static_cast<std::uint32_t>(total));
    u32(static_cast<std::uint32_t>(json_text.size()));
    u32(0x4E4F534Au);
    out.insert(out.end(), json_text.begin(), json_text.end());
    if (!bin.empty()) {
        u32(static_cast<std::uint32_t>(bin.size()));
        u32(0x004E4942u);
        out.insert(out.end(), bin.begin(), bin.end());
    }
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(out.data()), std::streamsize(out.size()));
}

}  // namespace
}  // namespace layout_test
