#include "assets/gltf_model.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <new>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <tiny_gltf.h>

#include "base/file_io.hpp"
#include "assets/gltf_accessor.hpp"
#include "assets/gltf_material.hpp"
#include "assets/gltf_preflight.hpp"
#include "assets/limits.hpp"
#include "base/file_io.hpp"
#include "base/format.hpp"
#include "base/user_text.hpp"

namespace impossible::assets {

namespace {

// --- tinygltf callbacks: no shell expansion of paths, no image decoding
// while parsing (keep_image_bytes keeps the bytes; only the images a drawn
// material needs are decoded), no writing, and file reads bounded like ours.
//
// A model reads files only in its own folder and below (its buffers): a URI
// such as "../../../../etc/passwd" must not open, or even reveal whether or
// how large, a file elsewhere. `user_data` is the model's folder, canonical.
bool inside_model_folder(const std::string& path, void* user_data) {
    return assets::inside_folder(path, *static_cast<const std::string*>(user_data));
}
bool fs_file_exists(const std::string& path, void* user_data) {
    if (!inside_model_folder(path, user_data)) return true;  // refused when read, whether it exists or not
    std::error_code ec;
    return std::filesystem::is_regular_file(path, ec);
}
std::string fs_expand_path(const std::string& path, void*) { return path; }
bool fs_read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                        void* user_data) {
    if (!inside_model_folder(path, user_data)) {
        if (err != nullptr) *err += "file " + quote(path) + " lies outside the model's folder\n";
        return false;
    }
    Result<std::vector<unsigned char>> bytes = read_file_bytes(path, limits::kMaxModelBytes, true);
    if (bytes) {
        *out = std::move(*bytes);
        return true;
    }
    if (err != nullptr) *err += "file " + quote(path) + " " + bytes.error() + "\n";
    return false;
}
bool fs_write_whole_file(std::string* err, const std::string&, const std::vector<unsigned char>&,
                         void*) {
    if (err != nullptr) *err += "writing is disabled\n";
    return false;
}
// tinygltf's first message, one short line; a data: URI in it (tinygltf
// quotes whole buffers) is cut to its media type.
std::string first_line(const std::string& text) {
    std::string line = text.substr(0, text.find('\n'));
    for (std::size_t at = line.find("data:"); at != std::string::npos; at = line.find("data:", at + 5)) {
        const std::size_t comma = line.find(',', at);
        if (comma == std::string::npos) break;
        std::size_t end = comma + 1;
        while (end < line.size() && !std::isspace(static_cast<unsigned char>(line[end]))) ++end;
        line.replace(comma + 1, end - comma - 1, "...");
    }
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
    if (line.size() > 200) line = line.substr(0, 200) + "...";
    return printable(line.empty() ? "unknown reason" : line);
}

bool all_finite(const std::vector<double>& v) {
    return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

std::string beyond_coordinate_limit() {
    return "beyond the 100 km coordinate limit (" + format_number(limits::kMaxCoordinate) + " m)";
}

// The node's local transform: its matrix, or translation · rotation · scale.
// Translations are coordinates (|t| <= 100 km) and scale factors are bounded
// like a prop's scale (|s| <= 1e6), so a finite but absurd node (a matrix of
// 1e300) is an error naming it rather than triangles that overflow.
Result<glm::dmat4> local_transform(const tinygltf::Node& node, int index) {
    const std::string who = "has node " + std::to_string(index);
    if (!all_finite(node.matrix) || !all_finite(node.translation) || !all_finite(node.rotation) ||
        !all_finite(node.scale)) {
        return Error{who + " with a non-finite transform"};
    }
    const auto check_scale = [&](double v, const char* field) -> Result<void> {
        if (std::abs(v) > limits::kMaxScale) {
            return Error{who + " whose " + field + " holds " + format_number(v) + ", beyond the scale limit of " +
                         format_number(limits::kMaxScale)};
        }
        return {};
    };
    const auto check_translation = [&](double v, const char* field) -> Result<void> {
        if (std::abs(v) > limits::kMaxCoordinate) {
            return Error{who + " whose " + field + " holds " + format_number(v) + ", " + beyond_coordinate_limit()};
        }
        return {};
    };
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16) {
            return Error{who + " whose matrix does not have 16 numbers"};
        }
        glm::dmat4 m(1.0);
        for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = node.matrix[static_cast<std::size_t>(i)];
        for (int c = 0; c < 3; ++c) {
            for (int r = 0; r < 3; ++r) {
                if (Result<void> ok = check_scale(m[c][r], "matrix"); !ok) return ok;
            }
            if (Result<void> ok = check_translation(m[3][c], "matrix translation"); !ok) return ok;
        }
        if (m[0][3] != 0.0 || m[1][3] != 0.0 || m[2][3] != 0.0 || m[3][3] != 1.0) {
            return Error{who + " whose matrix is not affine (its last row must be 0, 0, 0, 1)"};
        }
        return m;
    }
    if ((!node.translation.empty() && node.translation.size() != 3) ||
        (!node.rotation.empty() && node.rotation.size() != 4) ||
        (!node.scale.empty() && node.scale.size() != 3)) {
        return Error{who + " whose translation, rotation or scale has the wrong number of values"};
    }
    for (double v : node.translation) {
        if (Result<void> ok = check_translation(v, "translation"); !ok) return ok;
    }
    for (double v : node.scale) {
        if (Result<void> ok = check_scale(v, "scale"); !ok) return ok;
    }
    glm::dmat4 t(1.0), r(1.0), s(1.0);
    if (!node.translation.empty()) {
        t[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
    }
    if (!node.rotation.empty()) {
        double x = node.rotation[0], y = node.rotation[1], z = node.rotation[2], w = node.rotation[3];
        const double length = std::sqrt(x * x + y * y + z * z + w * w);
        if (!(length > 1e-12) || !std::isfinite(length)) {
            return Error{who + " whose rotation is not a unit quaternion"};
        }
        x /= length, y /= length, z /= length, w /= length;
        // Columns of the rotation matrix of the quaternion (x, y, z, w).
        r[0] = glm::dvec4(1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y), 0);
        r[1] = glm::dvec4(2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x), 0);
        r[2] = glm::dvec4(2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y), 0);
    }
    if (!node.scale.empty()) {
        s[0][0] = node.scale[0], s[1][1] = node.scale[1], s[2][2] = node.scale[2];
    }
    return t * r * s;
}

struct MeshInstance {
    int node = -1;
    int mesh = -1;
    glm::dmat4 world{1.0};
};

// Walks the default scene's node tree (iteratively, each node once).
Result<std::vector<MeshInstance>> collect_instances(const tinygltf::Model& model) {
    std::vector<MeshInstance> out;
    const std::size_t node_count = model.nodes.size();
    std::vector<int> roots;
    if (!model.scenes.empty()) {
        int scene = model.defaultScene < 0 ? 0 : model.defaultScene;
        if (static_cast<std::size_t>(scene) >= model.scenes.size()) {
            return Error{"names default scene " + std::to_string(scene) + ", which does not exist"};
        }
        roots = model.scenes[static_cast<std::size_t>(scene)].nodes;
    } else {
        std::vector<bool> is_child(node_count, false);
        for (const tinygltf::Node& node : model.nodes) {
            for (int c : node.children) {
                if (c >= 0 && static_cast<std::size_t>(c) < node_count) is_child[static_cast<std::size_t>(c)] = true;
            }
        }
        for (std::size_t i = 0; i < node_count; ++i) {
            if (!is_child[i]) roots.push_back(static_cast<int>(i));
        }
    }
    struct Item {
        int node;
        glm::dmat4 parent;
        std::size_t depth;
    };
    std::vector<Item> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, glm::dmat4(1.0), 1});
    std::vector<bool> visited(node_count, false);
    while (!stack.empty()) {
        const Item item = stack.back();
        stack.pop_back();
        if (item.node < 0 || static_cast<std::size_t>(item.node) >= node_count) {
            return Error{"refers to node " + std::to_string(item.node) + ", which does not exist"};
        }
        const auto index = static_cast<std::size_t>(item.node);
        if (visited[index]) {
            return Error{"reaches node " + std::to_string(item.node) +
                    " twice (its nodes must form a tree)"};
        }
        visited[index] = true;
        if (item.depth > limits::kMaxNodeDepth) {
            return Error{"has nodes nested deeper than " + std::to_string(limits::kMaxNodeDepth) + " levels"};
        }
        const tinygltf::Node& node = model.nodes[index];
        const Result<glm::dmat4> local = local_transform(node, item.node);
        if (!local) return local;
        const glm::dmat4 world = item.parent * *local;
        if (node.mesh >= 0) {
            if (static_cast<std::size_t>(node.mesh) >= model.meshes.size()) {
                return Error{"refers to mesh " + std::to_string(node.mesh) + ", which does not exist"};
            }
            out.push_back({item.node, node.mesh, world});
        }
        for (auto c = node.children.rbegin(); c != node.children.rend(); ++c) {
            stack.push_back({*c, world, item.depth + 1});
        }
    }
    return out;
}

glm::dvec3 base_colour(const tinygltf::Model& model, int material) {
    const glm::dvec3 grey(0.8);
    if (material < 0) return grey;  // read_primitive checked it exists
    const std::vector<double>& f =
        model.materials[static_cast<std::size_t>(material)].pbrMetallicRoughness.baseColorFactor;
    if (f.size() < 3 || !std::isfinite(f[0]) || !std::isfinite(f[1]) || !std::isfinite(f[2])) {
        return grey;
    }
    return glm::clamp(glm::dvec3(f[0], f[1], f[2]), 0.0, 1.0);
}

// Accessors copied (sparse, or without a bufferView) hold at most this many
// elements: three vertices for each triangle a model may have.
constexpr std::size_t kMaxCopied = 3 * limits::kMaxModelTriangles;

struct PrimitiveData {
    std::string name;         // "mesh 0 primitive 1"
    int position_accessor = -1;
    int mode = TINYGLTF_MODE_TRIANGLES;
    std::size_t corners = 0;  // vertices or indices
    AccessorView positions;
    AccessorView normals;  // count 0: none
    AccessorView indices;  // count 0 with data null: not indexed
    bool indexed = false;
    std::size_t triangles = 0;
    glm::dvec3 colour{0.8};
    int material = -1;        // the glTF material
    AccessorView colours;     // COLOR_0; count 0: none
    std::size_t colour_components = 0;  // 3 or 4
    AccessorView uvs;         // the base colour texture's TEXCOORD_n; count 0: none
};

// An attribute of a primitive that gives each vertex a few values (COLOR_0,
// TEXCOORD_n): float, or normalized unsigned byte or short.
Result<AccessorView> vertex_values(const tinygltf::Model& model, int index, int type, const std::string& what,
                                   std::size_t vertices) {
    Result<AccessorView> view = accessor_view(model, index, type,
                                              {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                               TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                                              what.c_str(), kMaxCopied);
    if (!view) return view;
    if (view->count != vertices) {
        return Error{what + " accessor " + std::to_string(index) + " has " + std::to_string(view->count) +
                     " values for " + std::to_string(vertices) + " vertices"};
    }
    const std::size_t components = type == TINYGLTF_TYPE_VEC2 ? 2 : type == TINYGLTF_TYPE_VEC3 ? 3 : 4;
    for (std::size_t i = 0; i < view->count; ++i) {
        for (std::size_t c = 0; c < components; ++c) {
            if (!std::isfinite(view->normalized(i, c))) {
                return Error{what + " accessor " + std::to_string(index) + " has a value that is not finite (vertex " +
                             std::to_string(i) + ")"};
            }
        }
    }
    return view;
}


Result<PrimitiveData> read_primitive(const tinygltf::Model& model, int mesh, std::size_t p) {
    PrimitiveData out;
    const tinygltf::Primitive& primitive = model.meshes[static_cast<std::size_t>(mesh)].primitives[p];
    const std::string name = "mesh " + std::to_string(mesh) + " primitive " + std::to_string(p);
    static const char* const mode_names[] = {"points", "lines", "line loop", "line strip"};
    out.name = name;
    out.mode = primitive.mode == -1 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
    if (out.mode != TINYGLTF_MODE_TRIANGLES && out.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        out.mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        const bool named = out.mode >= 0 && out.mode < 4;
        return Error{"has " + name + " in mode " + std::to_string(out.mode) +
                     (named ? std::string(" (") + mode_names[out.mode] + ")" : std::string()) +
                     "; only triangles, triangle strips and fans (modes 4, 5, 6) are supported"};
    }
    if (primitive.material < -1 ||
        (primitive.material >= 0 && static_cast<std::size_t>(primitive.material) >= model.materials.size())) {
        return Error{"has " + name + " whose material " + std::to_string(primitive.material) +
                     " does not exist (the model has " + std::to_string(model.materials.size()) + " materials)"};
    }
    const auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) {
        return Error{"has " + name + " without POSITION"};
    }
    const auto fail = [&](const std::string& reason) { return Error{"has " + name + " whose " + reason}; };
    if (Result<AccessorView> view = accessor_view(model, position->second, TINYGLTF_TYPE_VEC3,
                       {TINYGLTF_COMPONENT_TYPE_FLOAT}, "POSITION", kMaxCopied)) {
        out.positions = std::move(*view);
        out.position_accessor = position->second;
    } else {
        return fail(view.error());
    }
    const auto normal = primitive.attributes.find("NORMAL");
    if (normal != primitive.attributes.end()) {
        if (Result<AccessorView> view = accessor_view(model, normal->second, TINYGLTF_TYPE_VEC3,
                           {TINYGLTF_COMPONENT_TYPE_FLOAT}, "NORMAL", kMaxCopied)) {
        out.normals = std::move(*view);
    } else {
        return fail(view.error());
    }
        if (out.normals.count != out.positions.count) {
            return Error{"has " + name + " with a different number of normals and positions"};
        }
    }
    std::size_t corners = out.positions.count;
    if (primitive.indices >= 0) {
        if (Result<AccessorView> view = accessor_view(model, primitive.indices, TINYGLTF_TYPE_SCALAR,
                           {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                            TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                           "index", kMaxCopied)) {
        out.indices = std::move(*view);
    } else {
        return fail(view.error());
    }
        out.indexed = true;
        corners = out.indices.count;
    }
    if (out.mode == TINYGLTF_MODE_TRIANGLES && corners % 3 != 0) {
        return Error{"has " + name + " whose vertex count " + std::to_string(corners) +
                " is not a multiple of 3"};
    }
    out.corners = corners;
    out.triangles = out.mode == TINYGLTF_MODE_TRIANGLES ? corners / 3 : corners >= 3 ? corners - 2 : 0;
    out.material = primitive.material;
    int tex_coord = -1;
    if (primitive.material >= 0) {
        const Result<int> checked = check_material(model, primitive.material);
        if (!checked) return checked;
        tex_coord = *checked;
    }
    out.colour = base_colour(model, primitive.material);
    const auto colour = primitive.attributes.find("COLOR_0");
    if (colour != primitive.attributes.end()) {
        const int index = colour->second;
        const bool exists = index >= 0 && static_cast<std::size_t>(index) < model.accessors.size();
        const int type = exists ? model.accessors[static_cast<std::size_t>(index)].type : TINYGLTF_TYPE_VEC4;
        if (exists && type != TINYGLTF_TYPE_VEC3 && type != TINYGLTF_TYPE_VEC4) {
            return fail("COLOR_0 accessor " + std::to_string(index) + " must be VEC3 or VEC4");
        }
        Result<AccessorView> view = vertex_values(model, index, type, "COLOR_0", out.positions.count);
        if (!view) return fail(view.error());
        out.colours = std::move(*view);
        out.colour_components = type == TINYGLTF_TYPE_VEC3 ? 3 : 4;
    }
    if (tex_coord >= 0) {
        const std::string set = "TEXCOORD_" + std::to_string(tex_coord);
        const auto uv = primitive.attributes.find(set);
        if (uv == primitive.attributes.end()) {
            return Error{"has " + name + " whose material " + std::to_string(primitive.material) +
                         " reads its base colour texture with " + set + ", which the primitive does not have"};
        }
        Result<AccessorView> view = vertex_values(model, uv->second, TINYGLTF_TYPE_VEC2, set, out.positions.count);
        if (!view) return fail(view.error());
        out.uvs = std::move(*view);
    }
    return out;
}

bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool within(const glm::dvec3& v, double limit) {
    return std::abs(v.x) <= limit && std::abs(v.y) <= limit && std::abs(v.z) <= limit;
}

std::string format_vec(const glm::dvec3& v) {
    return "(" + format_number(v.x) + ", " + format_number(v.y) + ", " + format_number(v.z) + ")";
}

// Corner k of triangle t, as a position in the vertex list (glTF 2.0,
// "Primitive Topologies"): strips alternate their winding, fans turn about
// the first vertex.
std::size_t corner(const PrimitiveData& data, std::size_t t, std::size_t k) {
    std::size_t at = 3 * t + k;
    if (data.mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        const std::size_t odd = t % 2;
        at = k == 0 ? t : k == 1 ? t + 1 + odd : t + 2 - odd;
    } else if (data.mode == TINYGLTF_MODE_TRIANGLE_FAN) {
        at = k == 0 ? t + 1 : k == 1 ? t + 2 : 0;
    }
    return data.indexed ? data.indices.index(at) : at;
}

Result<void> emit_triangles(const PrimitiveData& data, const MeshInstance& instance,
                            std::vector<ModelTriangle>& out) {
    const glm::dmat4& world = instance.world;
    const glm::dmat3 linear(world);
    const double det = glm::determinant(linear);
    const bool mirrored = det < 0.0;
    const bool normals_usable = std::abs(det) > 1e-300 && data.normals.count > 0;
    const glm::dmat3 normal_matrix = normals_usable ? glm::transpose(glm::inverse(linear)) : linear;
    for (std::size_t t = 0; t < data.triangles; ++t) {
        std::size_t v[3];
        for (std::size_t k = 0; k < 3; ++k) {
            v[k] = corner(data, t, k);
            if (v[k] >= data.positions.count) {
                return Error{"has an index " + std::to_string(v[k]) + " past the end of its " +
                        std::to_string(data.positions.count) + " vertices"};
            }
        }
        if (mirrored) std::swap(v[1], v[2]);  // keep front faces counter-clockwise
        ModelTriangle triangle;
        for (std::size_t k = 0; k < 3; ++k) {
            const glm::dvec3 p = data.positions.vec3(v[k]);
            if (!finite(p) || !within(p, limits::kMaxCoordinate)) {
                return Error{"has " + data.name + " whose POSITION accessor " + std::to_string(data.position_accessor) +
                             " has vertex " + std::to_string(v[k]) + " at " + format_vec(p) + ", " +
                             beyond_coordinate_limit()};
            }
            triangle.position[k] = glm::dvec3(world * glm::dvec4(p, 1.0));
            if (!finite(triangle.position[k]) || !within(triangle.position[k], limits::kMaxCoordinate)) {
                return Error{"has node " + std::to_string(instance.node) + " that places vertex " +
                             std::to_string(v[k]) + " of " + data.name + " at " + format_vec(triangle.position[k]) +
                             ", " + beyond_coordinate_limit()};
            }
        }
        const glm::dvec3 cross = glm::cross(triangle.position[1] - triangle.position[0],
                                            triangle.position[2] - triangle.position[0]);
        const double area2 = glm::length(cross);
        if (!(area2 > 1e-300) || !std::isfinite(area2)) continue;  // degenerate: invisible
        const glm::dvec3 flat = cross / area2;
        for (std::size_t k = 0; k < 3; ++k) {
            glm::dvec3 n = flat;
            if (normals_usable) {
                const glm::dvec3 given = normal_matrix * data.normals.vec3(v[k]);
                const double length = glm::length(given);
                if (finite(given) && length > 1e-12 && std::isfinite(length)) n = given / length;
            }
            triangle.normal[k] = n;
        }
        triangle.color = data.colour;
        triangle.material = data.material;  // a glTF index until build_materials
        for (std::size_t k = 0; k < 3; ++k) {
            if (data.colours.count > 0) {
                glm::dvec4 c(1.0);
                for (std::size_t i = 0; i < data.colour_components; ++i) {
                    c[static_cast<int>(i)] = std::clamp(data.colours.normalized(v[k], i), 0.0, 1.0);
                }
                triangle.vertex_color[k] = c;
            }
            if (data.uvs.count > 0) triangle.uv[k] = {data.uvs.normalized(v[k], 0), data.uvs.normalized(v[k], 1)};
        }
        out.push_back(triangle);
    }
    return {};
}

Result<GltfModel> load_model(const std::string& path, std::size_t max_triangles) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    const bool binary = extension == ".glb";
    if (!binary && extension != ".gltf") {
        return Error{"is not a glTF model (expected a .glb or .gltf file)"};
    }
    // The file is read here, bounded, and checked before tinygltf sees it.
    Result<std::vector<unsigned char>> bytes = read_file_bytes(path, limits::kMaxModelBytes, true);
    if (!bytes) return bytes;
    if (bytes->empty()) {
        return Error{"is not a valid glTF 2.0 file: the file is empty"};
    }
    std::string_view json_text(reinterpret_cast<const char*>(bytes->data()), bytes->size());
    long long bin_size = -1;
    if (binary) {
        Result<GlbChunks> chunks = split_glb(*bytes);
        if (!chunks) return chunks;
        json_text = chunks->json;
        if (chunks->has_bin) bin_size = static_cast<long long>(chunks->bin_size);
    }
    if (Result<void> shape = check_json_shape(json_text); !shape) return shape;

    std::error_code ec;
    std::string folder =
        std::filesystem::weakly_canonical(std::filesystem::absolute(path, ec).parent_path(), ec).string();
    if (ec) return Error{"cannot be opened: " + ec.message()};
    while (folder.size() > 1 && folder.back() == '/') folder.pop_back();
    if (folder == "/") folder.clear();  // a model at the root: everything is below it
    if (Result<void> checked = check_gltf_document(json_text, binary, bin_size, folder); !checked)
        return checked;

    tinygltf::TinyGLTF loader;
    KeptImages kept;
    loader.SetImageLoader(&keep_image_bytes, &kept);
    loader.SetFsCallbacks({&fs_file_exists, &fs_expand_path, &fs_read_whole_file,
                           &fs_write_whole_file, &folder});
    tinygltf::Model model;
    std::string err, warn;
    const std::string base_dir = folder.empty() ? "/" : folder;
    const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes->data(),
                                                         static_cast<unsigned int>(bytes->size()), base_dir)
                           : loader.LoadASCIIFromString(&model, &err, &warn, json_text.data(),
                                                        static_cast<unsigned int>(json_text.size()), base_dir);
    if (!kept.error.empty()) return Error{kept.error};
    if (!ok) {
        return Error{"is not a valid glTF 2.0 file: " + first_line(err)};
    }
    if (model.asset.version.rfind("2.", 0) != 0) {
        return Error{"is glTF version " + quote(model.asset.version) + "; only 2.0 is supported"};
    }
    if (!model.extensionsRequired.empty()) {  // check_gltf_document refused them already
        return Error{"requires the unsupported glTF extension " + quote(model.extensionsRequired.front())};
    }
    const Result<std::vector<MeshInstance>> instances = collect_instances(model);
    if (!instances) return instances;

    // Check every primitive and count triangles before reading any.
    std::vector<std::pair<PrimitiveData, MeshInstance>> work;
    std::size_t triangles = 0;
    for (const MeshInstance& instance : *instances) {
        const auto& primitives = model.meshes[static_cast<std::size_t>(instance.mesh)].primitives;
        for (std::size_t p = 0; p < primitives.size(); ++p) {
            Result<PrimitiveData> data = read_primitive(model, instance.mesh, p);
            if (!data) return data;
            triangles += data->triangles;
            if (triangles > max_triangles) {
                return Error{"has more than " + std::to_string(max_triangles) + " triangles"};
            }
            work.emplace_back(std::move(*data), instance);
        }
    }
    GltfModel out;
    out.triangles.reserve(triangles);
    for (const auto& [data, instance] : work) {
        if (Result<void> emitted = emit_triangles(data, instance, out.triangles); !emitted)
            return emitted;
    }
    if (out.triangles.empty()) {
        return Error{"has no triangles"};
    }
    if (Result<void> built = build_materials(model, kept, folder, out.triangles, out.materials, out.textures,
                                             out.texels);
        !built) {
        return built;
    }
    return out;
}

}  // namespace

Result<GltfModel> load_gltf_model(const std::string& path, std::size_t max_triangles) {
    try {
        return load_model(path, max_triangles);
    } catch (const std::bad_alloc&) {
        return Error{"is too large to read (out of memory)"};
    } catch (const std::exception& e) {
        // tinygltf throws on some malformed input (e.g. std::out_of_range).
        return Error{"is not a valid glTF 2.0 file: " + printable(e.what())};
    }
}

Result<std::vector<ModelTriangle>> load_gltf_triangles(const std::string& path, std::size_t max_triangles) {
    Result<GltfModel> model = load_gltf_model(path, max_triangles);
    if (!model) return model;
    return std::move(model->triangles);
}

}  // namespace impossible::assets
