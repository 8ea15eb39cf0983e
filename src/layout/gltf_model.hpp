// Reads the triangles of a glTF 2.0 model (.glb or .gltf) with tinygltf.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "base/result.hpp"
#include "layout/layout.hpp"

namespace impossible::layout::detail {

// The triangles of the model's default scene (scene 0 when none is marked;
// every root node when the file has no scene), with the node transforms
// applied, in the model's own coordinates. Supports TRIANGLES primitives,
// indexed (8, 16 or 32-bit) or not, with float VEC3 positions; NORMAL is
// used when present, else flat normals are computed. Colour: the material's
// base colour factor (rgb), 0.8 grey without a material. Triangles are
// counter-clockwise seen from their front (mirroring nodes are turned back).
// Zero-area triangles are dropped.
//
// Returns an error (a sentence, without the file name) for a
// file that is missing, unreadable, not glTF, uses what is not supported, or
// has more than `max_triangles` triangles. Never throws for bad input.
Result<std::vector<ModelTriangle>> load_gltf_triangles(const std::string& path, std::size_t max_triangles);

}  // namespace impossible::layout::detail
