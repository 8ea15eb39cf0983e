// Primitive reading: a glTF primitive's accessors (positions, normals,
// indices, colours, texture coordinates), checked, and turned into triangles.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "assets/gltf_import.hpp"

namespace impossible::assets {

namespace {

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

// "has mesh 0 primitive 1 whose REASON".
Error primitive_error(const std::string& name, const std::string& reason) {
    return Error{"has " + name + " whose " + reason};
}

// An attribute of a primitive that gives each vertex a few values (COLOR_0,
// TEXCOORD_n): float, or normalized unsigned byte or short.
Result<AccessorView> vertex_values(const tinygltf::Model& model, int index, int type, const std::string& what,
                                   std::size_t vertices) {
    Result<AccessorView> view = accessor_view(
        model, index, type,
        {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
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

// The primitive's mode (TRIANGLES when absent), which must draw triangles.
Result<int> primitive_mode(const tinygltf::Primitive& primitive, const std::string& name) {
    static const char* const mode_names[] = {"points", "lines", "line loop", "line strip"};
    const int mode = primitive.mode == -1 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        const bool named = mode >= 0 && mode < 4;
        return Error{"has " + name + " in mode " + std::to_string(mode) +
                     (named ? std::string(" (") + mode_names[mode] + ")" : std::string()) +
                     "; only triangles, triangle strips and fans (modes 4, 5, 6) are supported"};
    }
    return mode;
}

// POSITION, NORMAL (if any) and the indices (if any), and so the number of
// corners and triangles.
Result<void> read_geometry(const tinygltf::Model& model, const tinygltf::Primitive& primitive, PrimitiveData& out) {
    const std::string& name = out.name;
    const auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) {
        return Error{"has " + name + " without POSITION"};
    }
    Result<AccessorView> positions = accessor_view(model, position->second, TINYGLTF_TYPE_VEC3,
                                                   {TINYGLTF_COMPONENT_TYPE_FLOAT}, "POSITION", kMaxCopied);
    if (!positions) return primitive_error(name, positions.error());
    out.positions = std::move(*positions);
    out.position_accessor = position->second;
    const auto normal = primitive.attributes.find("NORMAL");
    if (normal != primitive.attributes.end()) {
        Result<AccessorView> normals = accessor_view(model, normal->second, TINYGLTF_TYPE_VEC3,
                                                     {TINYGLTF_COMPONENT_TYPE_FLOAT}, "NORMAL", kMaxCopied);
        if (!normals) return primitive_error(name, normals.error());
        out.normals = std::move(*normals);
        if (out.normals.count != out.positions.count) {
            return Error{"has " + name + " with a different number of normals and positions"};
        }
    }
    std::size_t corners = out.positions.count;
    if (primitive.indices >= 0) {
        Result<AccessorView> indices =
            accessor_view(model, primitive.indices, TINYGLTF_TYPE_SCALAR,
                          {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                           TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                          "index", kMaxCopied);
        if (!indices) return primitive_error(name, indices.error());
        out.indices = std::move(*indices);
        out.indexed = true;
        corners = out.indices.count;
    }
    if (out.mode == TINYGLTF_MODE_TRIANGLES && corners % 3 != 0) {
        return Error{"has " + name + " whose vertex count " + std::to_string(corners) + " is not a multiple of 3"};
    }
    out.corners = corners;
    out.triangles = out.mode == TINYGLTF_MODE_TRIANGLES ? corners / 3 : corners >= 3 ? corners - 2 : 0;
    return {};
}

// COLOR_0, a VEC3 or VEC4 of colours, one for each vertex.
Result<void> read_vertex_colours(const tinygltf::Model& model, int index, PrimitiveData& out) {
    const bool exists = index >= 0 && static_cast<std::size_t>(index) < model.accessors.size();
    const int type = exists ? model.accessors[static_cast<std::size_t>(index)].type : TINYGLTF_TYPE_VEC4;
    if (exists && type != TINYGLTF_TYPE_VEC3 && type != TINYGLTF_TYPE_VEC4) {
        return primitive_error(out.name, "COLOR_0 accessor " + std::to_string(index) + " must be VEC3 or VEC4");
    }
    Result<AccessorView> view = vertex_values(model, index, type, "COLOR_0", out.positions.count);
    if (!view) return primitive_error(out.name, view.error());
    out.colours = std::move(*view);
    out.colour_components = type == TINYGLTF_TYPE_VEC3 ? 3 : 4;
    return {};
}

// The material (checked), its base colour, COLOR_0 and the texture
// coordinates its base colour texture reads.
Result<void> read_appearance(const tinygltf::Model& model, const tinygltf::Primitive& primitive, PrimitiveData& out) {
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
        if (Result<void> read = read_vertex_colours(model, colour->second, out); !read) return read;
    }
    if (tex_coord >= 0) {
        const std::string set = "TEXCOORD_" + std::to_string(tex_coord);
        const auto uv = primitive.attributes.find(set);
        if (uv == primitive.attributes.end()) {
            return Error{"has " + out.name + " whose material " + std::to_string(primitive.material) +
                         " reads its base colour texture with " + set + ", which the primitive does not have"};
        }
        Result<AccessorView> view = vertex_values(model, uv->second, TINYGLTF_TYPE_VEC2, set, out.positions.count);
        if (!view) return primitive_error(out.name, view.error());
        out.uvs = std::move(*view);
    }
    return {};
}

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

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

// The vertices of triangle t, each checked to exist.
Result<void> triangle_vertices(const PrimitiveData& data, std::size_t t, std::size_t (&v)[3]) {
    for (std::size_t k = 0; k < 3; ++k) {
        v[k] = corner(data, t, k);
        if (v[k] >= data.positions.count) {
            return Error{"has an index " + std::to_string(v[k]) + " past the end of its " +
                         std::to_string(data.positions.count) + " vertices"};
        }
    }
    return {};
}

// The positions of vertices v placed by the instance, each checked before
// and after against the coordinate limit.
Result<void> place_vertices(const PrimitiveData& data, const MeshInstance& instance, const std::size_t (&v)[3],
                            ModelTriangle& triangle) {
    for (std::size_t k = 0; k < 3; ++k) {
        const glm::dvec3 p = data.positions.vec3(v[k]);
        if (!finite(p) || !within(p, limits::kMaxCoordinate)) {
            return Error{"has " + data.name + " whose POSITION accessor " + std::to_string(data.position_accessor) +
                         " has vertex " + std::to_string(v[k]) + " at " + format_vec(p) + ", " +
                         beyond_coordinate_limit()};
        }
        triangle.position[k] = glm::dvec3(instance.world * glm::dvec4(p, 1.0));
        if (!finite(triangle.position[k]) || !within(triangle.position[k], limits::kMaxCoordinate)) {
            return Error{"has node " + std::to_string(instance.node) + " that places vertex " + std::to_string(v[k]) +
                         " of " + data.name + " at " + format_vec(triangle.position[k]) + ", " +
                         beyond_coordinate_limit()};
        }
    }
    return {};
}

// COLOR_0 and the texture coordinates of vertices v, where the primitive
// has them.
void set_vertex_attributes(const PrimitiveData& data, const std::size_t (&v)[3], ModelTriangle& triangle) {
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
}

}  // namespace

Result<PrimitiveData> read_primitive(const tinygltf::Model& model, int mesh, std::size_t p) {
    PrimitiveData out;
    const tinygltf::Primitive& primitive = model.meshes[static_cast<std::size_t>(mesh)].primitives[p];
    const std::string name = "mesh " + std::to_string(mesh) + " primitive " + std::to_string(p);
    out.name = name;
    const Result<int> mode = primitive_mode(primitive, name);
    if (!mode) return mode;
    out.mode = *mode;
    if (primitive.material < -1 ||
        (primitive.material >= 0 && static_cast<std::size_t>(primitive.material) >= model.materials.size())) {
        return Error{"has " + name + " whose material " + std::to_string(primitive.material) +
                     " does not exist (the model has " + std::to_string(model.materials.size()) + " materials)"};
    }
    if (Result<void> read = read_geometry(model, primitive, out); !read) return read;
    if (Result<void> read = read_appearance(model, primitive, out); !read) return read;
    return out;
}

Result<void> emit_triangles(const PrimitiveData& data, const MeshInstance& instance, std::vector<ModelTriangle>& out) {
    const glm::dmat3 linear(instance.world);
    const double det = glm::determinant(linear);
    const bool mirrored = det < 0.0;
    const bool normals_usable = std::abs(det) > 1e-300 && data.normals.count > 0;
    const glm::dmat3 normal_matrix = normals_usable ? glm::transpose(glm::inverse(linear)) : linear;
    for (std::size_t t = 0; t < data.triangles; ++t) {
        std::size_t v[3];
        if (Result<void> found = triangle_vertices(data, t, v); !found) return found;
        if (mirrored) std::swap(v[1], v[2]);  // keep front faces counter-clockwise
        ModelTriangle triangle;
        if (Result<void> placed = place_vertices(data, instance, v, triangle); !placed) return placed;
        const glm::dvec3 cross =
            glm::cross(triangle.position[1] - triangle.position[0], triangle.position[2] - triangle.position[0]);
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
        set_vertex_attributes(data, v, triangle);
        out.push_back(triangle);
    }
    return {};
}

}  // namespace impossible::assets
