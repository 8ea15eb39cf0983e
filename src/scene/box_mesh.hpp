// Prop meshes: axis-aligned boxes seen from outside, and glTF models placed
// in the room.
#pragma once

#include <vector>

#include "layout/layout.hpp"
#include "scene/mesh_writer.hpp"

namespace impossible::scene {

// Six faces facing outwards, flat normals, the prop's colour, checker 0.
void append_box_prop(MeshWriter& out, const layout::BoxProp& box);

// The model's triangles moved by layout::place_model_point/normal, winding
// kept (glTF front faces are counter-clockwise), checker 0. Triangles are
// grouped by draw state (texture, alpha cutoff), each group appended to
// `batches`; a double-sided triangle is written twice, its back reversed.
void append_gltf_prop(MeshWriter& out, const layout::GltfProp& prop, std::vector<DrawBatch>& batches);

}  // namespace impossible::scene
