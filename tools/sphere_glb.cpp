#include "sphere_glb.hpp"
#include "glb_container.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

namespace impossible::tools {

namespace {

template <class T>
void append_values(std::vector<unsigned char>& out, const std::vector<T>& values) {
    for (const T& v : values) {
        std::uint32_t bits = 0;
        static_assert(sizeof(T) == 4);
        std::memcpy(&bits, &v, 4);
        append_u32(out, bits);
    }
}

std::string number(float v) { return json_number(v); }

// The sphere's vertices, their bounds and its triangles.
struct SphereMesh {
    std::vector<float> positions, normals;
    std::array<float, 3> lo = {1e30f, 1e30f, 1e30f}, hi = {-1e30f, -1e30f, -1e30f};
    std::vector<std::uint32_t> indices;
};

// (stacks + 1) rings of (slices + 1) vertices: the seam and the poles repeat.
void add_sphere_vertices(SphereMesh& mesh, int stacks, int slices) {
    const double pi = std::acos(-1.0);
    for (int i = 0; i <= stacks; ++i) {
        for (int j = 0; j <= slices; ++j) {
            const double theta = pi * i / stacks, phi = 2.0 * pi * j / slices;
            const double n[3] = {std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi)};
            const double r = 1.0 + 0.03 * std::sin(17.0 * n[0]) * std::sin(13.0 * n[1] + 11.0 * n[2]);
            for (int k = 0; k < 3; ++k) {
                const auto p = static_cast<float>(r * n[k]);
                mesh.positions.push_back(p);
                mesh.normals.push_back(static_cast<float>(n[k]));
                mesh.lo[k] = std::min(mesh.lo[k], p);
                mesh.hi[k] = std::max(mesh.hi[k], p);
            }
        }
    }
}

void add_sphere_triangles(SphereMesh& mesh, int stacks, int slices) {
    auto vertex = [&](int i, int j) { return static_cast<std::uint32_t>(i * (slices + 1) + j); };
    for (int i = 0; i < stacks; ++i) {
        for (int j = 0; j < slices; ++j) {
            // Counter-clockwise seen from outside.
            if (i > 0) mesh.indices.insert(mesh.indices.end(), {vertex(i, j), vertex(i + 1, j), vertex(i, j + 1)});
            if (i + 1 < stacks)
                mesh.indices.insert(mesh.indices.end(), {vertex(i, j + 1), vertex(i + 1, j), vertex(i + 1, j + 1)});
        }
    }
}

// The glTF JSON of the sphere whose buffer (positions, normals, indices)
// holds `bin_size` bytes, padded to a multiple of 4 bytes.
std::string sphere_json(const SphereMesh& mesh, std::size_t bin_size) {
    const std::size_t vertex_bytes = mesh.positions.size() * 4;
    const std::string count = std::to_string(mesh.positions.size() / 3);
    const std::array<float, 3>& lo = mesh.lo;
    const std::array<float, 3>& hi = mesh.hi;
    std::string json =
        "{\"asset\":{\"version\":\"2.0\",\"generator\":\"impossible tools/make_sphere_glb\"},"
        "\"scene\":0,\"scenes\":[{\"nodes\":[0]}],"
        "\"nodes\":[{\"name\":\"sphere\",\"mesh\":0}],"
        "\"meshes\":[{\"name\":\"sphere\",\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1},"
        "\"indices\":2,\"material\":0}]}],"
        "\"materials\":[{\"name\":\"clay\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.75,0.45,0.3,1],"
        "\"metallicFactor\":0,\"roughnessFactor\":1}}],"
        "\"accessors\":["
        "{\"bufferView\":0,\"componentType\":5126,\"count\":" +
        count + ",\"type\":\"VEC3\",\"min\":[" + number(lo[0]) + "," + number(lo[1]) + "," + number(lo[2]) +
        "],\"max\":[" + number(hi[0]) + "," + number(hi[1]) + "," + number(hi[2]) +
        "]},"
        "{\"bufferView\":1,\"componentType\":5126,\"count\":" +
        count +
        ",\"type\":\"VEC3\"},"
        "{\"bufferView\":2,\"componentType\":5125,\"count\":" +
        std::to_string(mesh.indices.size()) +
        ",\"type\":\"SCALAR\"}],"
        "\"bufferViews\":["
        "{\"buffer\":0,\"byteOffset\":0,\"byteLength\":" +
        std::to_string(vertex_bytes) +
        ",\"target\":34962},"
        "{\"buffer\":0,\"byteOffset\":" +
        std::to_string(vertex_bytes) + ",\"byteLength\":" + std::to_string(vertex_bytes) +
        ",\"target\":34962},"
        "{\"buffer\":0,\"byteOffset\":" +
        std::to_string(2 * vertex_bytes) + ",\"byteLength\":" + std::to_string(mesh.indices.size() * 4) +
        ",\"target\":34963}],"
        "\"buffers\":[{\"byteLength\":" +
        std::to_string(bin_size) + "}]}";
    while (json.size() % 4 != 0) json += ' ';  // chunks are 4-byte aligned
    return json;
}

}  // namespace

std::vector<unsigned char> make_sphere_glb(long triangles) {
    const int stacks = std::max(2, static_cast<int>(std::sqrt(static_cast<double>(std::max(16L, triangles)) / 4.0)));
    const int slices = 2 * stacks;
    SphereMesh mesh;
    add_sphere_vertices(mesh, stacks, slices);
    add_sphere_triangles(mesh, stacks, slices);
    std::vector<unsigned char> bin;
    append_values(bin, mesh.positions);
    append_values(bin, mesh.normals);
    append_values(bin, mesh.indices);
    return glb_of(sphere_json(mesh, bin.size()), bin);
}

}  // namespace impossible::tools
