// The meshes of the dynamic objects (walk/objects.hpp): each dynamic prop's
// and the hand's, appended after every cell and portal box so that the
// cells' index ranges are those of a layout without them.
#pragma once

#include "layout/layout.hpp"
#include "scene/mesh_writer.hpp"
#include "scene/scene.hpp"

namespace impossible::scene {

// Fills scene.object_meshes from scene.object_set: per dynamic prop (in
// object_set.props order) its triangles in the layout's coordinates as
// written, measured from its listed room's cell origin; then the hand
// (layout.hands): a box of HandShape::box centred on its frame's origin in
// HandShape::color, or the model at position 0, yaw 0 and its scale.
void append_object_meshes(Scene& scene, MeshWriter& out, const layout::Layout& layout);

}  // namespace impossible::scene
