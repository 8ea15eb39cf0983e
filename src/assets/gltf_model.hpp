// Reads the triangles of a glTF 2.0 model (.glb or .gltf) with tinygltf.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "assets/model.hpp"
#include "base/result.hpp"

namespace impossible::assets {

// The triangles of the model's default scene (scene 0 when none is marked;
// every root node when the file has no scene), with the node transforms
// applied, in the model's own coordinates. Supports TRIANGLES primitives,
// indexed (8, 16 or 32-bit) or not, with float VEC3 positions; NORMAL is
// used when present, else flat normals are computed. Colour: the material's
// base colour factor (rgb), 0.8 grey without a material. Triangles are
// counter-clockwise seen from their front (mirroring nodes are turned back).
// Zero-area triangles are dropped.
//
// Materials (docs/layouts.md, "Materials"): each triangle's `material`
// indexes `materials`, which holds only the materials the triangles use;
// `textures` only those the materials use, each image decoded once. COLOR_0
// fills vertex_color, the base colour texture's TEXCOORD set fills uv.
//
// Returns an error (a sentence, without the file name) for a
// file that is missing, unreadable, not glTF, uses what is not supported
// (images that are not PNG or JPEG), or has more than
// `max_triangles` triangles. Never throws for bad input.
struct GltfModel {
    std::vector<ModelTriangle> triangles;
    std::vector<Material> materials;
    std::vector<Texture> textures;
    std::size_t texels = 0;  // decoded, all images together (each once)
    // KHR_lights_punctual point and spot lights of the default scene's nodes,
    // in the model's coordinates (layout-format.md, "Lights").
    std::vector<ModelLight> lights;
    // The directional lights of those nodes, which are not kept (a layout
    // has none), each named as ModelLight::name; the loader warns of them.
    std::vector<std::string> directional_lights;
    // Every file read: the model's own path first, then its buffers and
    // images as tinygltf opened them (in the model's folder).
    std::vector<std::string> files;
};
Result<GltfModel> load_gltf_model(const std::string& path, std::size_t max_triangles);

// The triangles of load_gltf_model alone.
Result<std::vector<ModelTriangle>> load_gltf_triangles(const std::string& path, std::size_t max_triangles);

}  // namespace impossible::assets
