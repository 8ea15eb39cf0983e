// glTF materials, textures, samplers and images (internal to load_gltf_model):
// the checks on a material a primitive uses, the image callback tinygltf
// calls while parsing, and the decoding of the images the triangles need.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "assets/model.hpp"
#include "base/result.hpp"

namespace tinygltf {
class Model;
struct Image;
}  // namespace tinygltf

namespace impossible::assets {

// What tinygltf handed to keep_image_bytes, by image index. Images in a
// bufferView are read from the model's buffer later; the bytes of data: URIs
// and external files are copied here (at most limits::kMaxModelBytes in all).
// Nothing is decoded while parsing: only the images a drawn material needs are.
struct KeptImages {
    std::vector<std::vector<unsigned char>> bytes;
    std::vector<bool> delivered;
    std::size_t total = 0;
    std::string error;  // set when the callback refused (then it returned false)
};

// tinygltf's LoadImageDataFunction; `user_data` is a KeptImages.
bool keep_image_bytes(tinygltf::Image* image, int index, std::string* err, std::string* warn, int req_width,
                      int req_height, const unsigned char* bytes, int size, void* user_data);

// Checks material `material` (which exists) as a primitive uses it: factors,
// alphaMode (BLEND is refused), its base colour texture, that texture's
// sampler and source image. Returns the TEXCOORD set the texture reads, or -1
// without a texture. Errors follow "the model X ": "has material 2 ...".
Result<int> check_material(const tinygltf::Model& model, int material);

// The materials the triangles use, their textures and decoded images. On
// entry each triangle's `material` is a glTF material index (or -1); on
// return it indexes `materials`, which keeps only those used, in order of
// first use; `textures` likewise, each image decoded once (shared). `folder`
// is the model's folder ("" for the root), for messages about image files.
// `texels` returns the decoded texels (at most limits::kMaxModelTexels).
Result<void> build_materials(const tinygltf::Model& model, const KeptImages& kept, const std::string& folder,
                             std::vector<ModelTriangle>& triangles, std::vector<Material>& materials,
                             std::vector<Texture>& textures, std::size_t& texels);

}  // namespace impossible::assets
