// The faces of a prism room (layout-format.md, "Rooms of any shape"), seen
// from inside, with exact holes where its own portals lie in them: the floor,
// the ceiling and one wall per edge of the floor polygon, in face order
// (layout/room_shape.hpp).
//
// Walls (scene/prism_plan.hpp says how they are cut): a wall with holes is
// cut into a grid in its own frame (s along the wall, t = y), on s at its
// ends and the edges of its holes, on t at the floor, the ceiling and the
// top and bottom edges of the holes of its run of neighbouring walls with
// holes, and emits the cells no hole covers; a hole's portal front is built
// from the same grid points. Every other wall (no holes, or a rectangle
// that is not upright in it) is triangulated by the GLU tessellator
// (polygon_tess.hpp) with the heights of the grids beside it on its sides,
// so that neighbouring walls meet vertex to vertex; its portals' fronts are
// made of the holes' corners.
//
// Floor and ceiling: the floor polygon with every wall's grid points along
// its edges (so that floor and walls meet vertex to vertex) and the holes of
// trapdoors, triangulated by the tessellator; a trapdoor's front is made of
// its hole's corners, projected into the face's plane.
//
// Every vertex is computed once in double, in layout coordinates, and
// converted to the mesh's local coordinates (MeshWriter::local) once, so the
// faces and fronts that share a point share it bit for bit. Wall corners are
// the polygon's corners exactly. Each vertex carries its face's exact normal
// (layout::face_frame's), rounded to float so that the checker's dominant
// axis stays the one the exact normal has.
#pragma once

#include <optional>
#include <vector>

#include "layout/layout.hpp"
#include "scene/mesh_writer.hpp"
#include "scene/portal_box.hpp"

namespace impossible::scene {

// As append_room_faces (room_mesh.hpp) for a prism room: returns
// layout::face_count(room) index ranges, floor, ceiling, then wall 0, 1, …
std::vector<IndexRange> append_prism_faces(MeshWriter& out, const layout::Layout& layout, int room,
                                           const std::vector<int>& room_portals,
                                           std::vector<std::optional<FrontGrid>>& fronts);

}  // namespace impossible::scene
