#include "chair_glb.hpp"
#include "glb_container.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>

namespace impossible::tools {

namespace {

struct Box {
    std::array<float, 3> min;
    std::array<float, 3> max;
};

// One primitive's arrays: positions and normals (floats), 16-bit indices.
struct Arrays {
    std::vector<float> positions;
    std::vector<float> normals;
    std::vector<std::uint16_t> indices;
};

// Appends a box as 6 faces of 4 vertices, each face counter-clockwise seen
// from outside, with its outward normal.
void add_box(Arrays& out, const Box& box) {
    for (int axis = 0; axis < 3; ++axis) {
        // (b, c) span the face so that b × c points along +axis.
        const int b = (axis + 1) % 3;
        const int c = (axis + 2) % 3;
        for (int side = 0; side < 2; ++side) {
            const float sign = side == 0 ? -1.0f : 1.0f;
            const float plane = side == 0 ? box.min[axis] : box.max[axis];
            // Corners (b, c) in counter-clockwise order seen from the outside.
            std::array<std::array<int, 2>, 4> order = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
            if (side == 0) order = {{{0, 0}, {0, 1}, {1, 1}, {1, 0}}};
            const auto first = static_cast<std::uint16_t>(out.positions.size() / 3);
            for (const auto& corner : order) {
                std::array<float, 3> p{};
                p[axis] = plane;
                p[b] = corner[0] == 0 ? box.min[b] : box.max[b];
                p[c] = corner[1] == 0 ? box.min[c] : box.max[c];
                out.positions.insert(out.positions.end(), p.begin(), p.end());
                std::array<float, 3> n{};
                n[axis] = sign;
                out.normals.insert(out.normals.end(), n.begin(), n.end());
            }
            for (const int k : {0, 1, 2, 0, 2, 3}) {
                out.indices.push_back(static_cast<std::uint16_t>(first + k));
            }
        }
    }
}

template <class T>
void append_bytes(std::vector<unsigned char>& out, const std::vector<T>& values) {
    const std::size_t begin = out.size();
    out.resize(begin + values.size() * sizeof(T));
    std::memcpy(out.data() + begin, values.data(), values.size() * sizeof(T));
}

std::string number(float v) { return json_number(v); }

std::string vec3_json(const std::array<float, 3>& v) {
    return "[" + number(v[0]) + "," + number(v[1]) + "," + number(v[2]) + "]";
}

// Metres; the chair stands on y = 0, centred on x and z, its back at -z so
// that it faces +z (glTF's "front"). [0]: wood, [1]: the fabric cushion.
std::array<Arrays, 2> chair_parts() {
    const float leg = 0.04f;
    const float seat_height = 0.43f;
    const float half = 0.22f;
    Arrays wood;
    for (const float x : {-half, half - leg}) {
        for (const float z : {-half, half - leg}) {
            add_box(wood, {{x, 0.0f, z}, {x + leg, seat_height, z + leg}});
        }
    }
    add_box(wood, {{-half, seat_height, -half}, {half, seat_height + 0.04f, half}});     // seat
    add_box(wood, {{-half, seat_height + 0.04f, -half}, {half, 0.92f, -half + 0.04f}});  // back
    Arrays fabric;
    add_box(fabric, {{-half + 0.02f, seat_height + 0.04f, -half + 0.04f},
                     {half - 0.02f, seat_height + 0.09f, half - 0.02f}});  // cushion
    return {std::move(wood), std::move(fabric)};
}

struct BufferView {
    std::size_t offset, length;
    int target;
};

// The accessors and mesh primitives of the parts, whose buffer views are
// positions, normals and indices in turn: JSON array contents.
std::pair<std::string, std::string> accessors_and_primitives(const std::array<Arrays, 2>& parts) {
    std::string accessors;
    std::string mesh_primitives;
    for (int p = 0; p < 2; ++p) {
        const Arrays& a = parts[static_cast<std::size_t>(p)];
        std::array<float, 3> lo = {a.positions[0], a.positions[1], a.positions[2]};
        std::array<float, 3> hi = lo;
        for (std::size_t i = 0; i < a.positions.size(); ++i) {
            lo[i % 3] = std::min(lo[i % 3], a.positions[i]);
            hi[i % 3] = std::max(hi[i % 3], a.positions[i]);
        }
        const std::string count = std::to_string(a.positions.size() / 3);
        const int base = 3 * p;
        if (p > 0) accessors += ",";
        accessors += "{\"bufferView\":" + std::to_string(base) + ",\"componentType\":5126,\"count\":" + count +
                     ",\"type\":\"VEC3\",\"min\":" + vec3_json(lo) + ",\"max\":" + vec3_json(hi) + "}";
        accessors += ",{\"bufferView\":" + std::to_string(base + 1) + ",\"componentType\":5126,\"count\":" + count +
                     ",\"type\":\"VEC3\"}";
        accessors += ",{\"bufferView\":" + std::to_string(base + 2) +
                     ",\"componentType\":5123,\"count\":" + std::to_string(a.indices.size()) + ",\"type\":\"SCALAR\"}";
        if (p > 0) mesh_primitives += ",";
        mesh_primitives += "{\"attributes\":{\"POSITION\":" + std::to_string(base) +
                           ",\"NORMAL\":" + std::to_string(base + 1) + "},\"indices\":" + std::to_string(base + 2) +
                           ",\"material\":" + std::to_string(p) + "}";
    }
    return {accessors, mesh_primitives};
}

std::string buffer_views_json(const std::vector<BufferView>& views) {
    std::string out;
    for (std::size_t i = 0; i < views.size(); ++i) {
        if (i > 0) out += ",";
        out += "{\"buffer\":0,\"byteOffset\":" + std::to_string(views[i].offset) +
               ",\"byteLength\":" + std::to_string(views[i].length) + ",\"target\":" + std::to_string(views[i].target) +
               "}";
    }
    return out;
}

}  // namespace

std::vector<unsigned char> make_chair_glb() {
    const std::array<Arrays, 2> parts = chair_parts();
    // The binary chunk: each primitive's positions, normals, then indices.
    std::vector<unsigned char> bin;
    std::vector<BufferView> views;
    const auto add_view = [&](const auto& values, int target) {
        const std::size_t offset = bin.size();
        append_bytes(bin, values);
        views.push_back({offset, bin.size() - offset, target});
        while (bin.size() % 4 != 0) bin.push_back(0);  // keep every view 4-byte aligned
    };
    for (const Arrays& a : parts) {
        add_view(a.positions, 34962);
        add_view(a.normals, 34962);
        add_view(a.indices, 34963);
    }
    const auto [accessors, mesh_primitives] = accessors_and_primitives(parts);
    std::string json =
        "{\"asset\":{\"version\":\"2.0\",\"generator\":\"impossible tools/make_glb\"},"
        "\"scene\":0,\"scenes\":[{\"nodes\":[0]}],"
        "\"nodes\":[{\"name\":\"chair\",\"mesh\":0}],"
        "\"meshes\":[{\"name\":\"chair\",\"primitives\":[" +
        mesh_primitives +
        "]}],"
        "\"materials\":["
        "{\"name\":\"wood\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.55,0.35,0.2,1],"
        "\"metallicFactor\":0,\"roughnessFactor\":0.8}},"
        "{\"name\":\"fabric\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.7,0.12,0.1,1],"
        "\"metallicFactor\":0,\"roughnessFactor\":1}}],"
        "\"accessors\":[" +
        accessors +
        "],"
        "\"bufferViews\":[" +
        buffer_views_json(views) +
        "],"
        "\"buffers\":[{\"byteLength\":" +
        std::to_string(bin.size()) + "}]}";
    while (json.size() % 4 != 0) json += ' ';  // chunks are 4-byte aligned
    return glb_of(json, bin);
}

}  // namespace impossible::tools
