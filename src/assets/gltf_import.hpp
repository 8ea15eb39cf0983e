// The steps of load_gltf_model (internal to assets; gltf_model.cpp runs them):
// tinygltf confined to the model's folder (gltf_sandbox.cpp), the walk of the
// node tree (gltf_nodes.cpp) and the reading of primitives into triangles
// (gltf_primitives.cpp). Errors follow "the model X ": "has node 3 ...".
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <tiny_gltf.h>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "assets/gltf_accessor.hpp"
#include "assets/gltf_material.hpp"
#include "assets/limits.hpp"
#include "assets/model.hpp"
#include "base/format.hpp"
#include "base/result.hpp"

namespace impossible::assets {

// The end of messages about a coordinate that is too large.
inline std::string beyond_coordinate_limit() {
    return "beyond the 100 km coordinate limit (" + format_number(limits::kMaxCoordinate) + " m)";
}

// --- gltf_sandbox.cpp

// Parses a model's bytes (a .glb, or a .gltf whose JSON text is
// `json_text`) into `model` with tinygltf: no shell expansion of paths, no
// writing, file reads bounded like ours and only in `folder` (canonical, ""
// for the root) and below, and no image decoding (the bytes go to `kept`).
// The path of every file it reads (buffers, images) is appended to
// `files_read`. Errors: the image callback's refusal, or "is not a valid
// glTF 2.0 file: " and tinygltf's first message.
Result<void> parse_sandboxed(const std::vector<unsigned char>& bytes, std::string_view json_text, bool binary,
                             const std::string& folder, KeptImages& kept, tinygltf::Model& model,
                             std::vector<std::string>& files_read);

// --- gltf_nodes.cpp

// A node that draws a mesh, with its transform to the model's coordinates.
struct MeshInstance {
    int node = -1;
    int mesh = -1;
    glm::dmat4 world{1.0};
};

// A node that holds a KHR_lights_punctual light ({"light": N} in its
// extensions; N not yet checked), with its transform.
struct LightInstance {
    int node = -1;
    const tinygltf::Value* light = nullptr;  // the extension's "light" value
    glm::dmat4 world{1.0};
};

// Walks the default scene's node tree (iteratively, each node once): the
// nodes with a mesh, in document order of the tree; the nodes with a light
// are appended to `lights` in the same order.
Result<std::vector<MeshInstance>> collect_instances(const tinygltf::Model& model, std::vector<LightInstance>& lights);

// --- gltf_lights.cpp

// The point and spot lights of the nodes `lights` (layout-format.md,
// "Lights"), in the model's coordinates: position the node's origin, a
// spot's axis its -Z. Directional lights are skipped (a layout has none):
// their names (as ModelLight::name) go to `directional`.
// Errors name the node or the light: an index that does not exist, an
// unknown type, a colour outside 0..1, an intensity not > 0, a range not
// > 0, a cone not 0 <= inner < outer <= pi/2, or more than kMaxModelLights.
Result<std::vector<ModelLight>> read_lights(const tinygltf::Model& model, const std::vector<LightInstance>& lights,
                                            std::vector<std::string>& directional);

// --- gltf_primitives.cpp

struct PrimitiveData {
    std::string name;  // "mesh 0 primitive 1"
    int position_accessor = -1;
    int mode = TINYGLTF_MODE_TRIANGLES;
    std::size_t corners = 0;  // vertices or indices
    AccessorView positions;
    AccessorView normals;  // count 0: none
    AccessorView indices;  // count 0 with data null: not indexed
    bool indexed = false;
    std::size_t triangles = 0;
    glm::dvec3 colour{0.8};
    int material = -1;                  // the glTF material
    AccessorView colours;               // COLOR_0; count 0: none
    std::size_t colour_components = 0;  // 3 or 4
    AccessorView uvs;                   // the base colour texture's TEXCOORD_n; count 0: none
};

// Checks primitive `p` of mesh `mesh` (which exists) and views its accessors.
Result<PrimitiveData> read_primitive(const tinygltf::Model& model, int mesh, std::size_t p);

// Appends the primitive's triangles, placed by the instance, to `out`.
Result<void> emit_triangles(const PrimitiveData& data, const MeshInstance& instance, std::vector<ModelTriangle>& out);

}  // namespace impossible::assets
