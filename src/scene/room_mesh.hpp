// A room's faces, seen from inside, with exact rectangular holes where its
// own portals lie in them (layout-format.md, "Rooms" and "The portal box").
// Which portal is a hole in which face is the loader's decision
// (layout::Portal::hole_face), so the rasteriser and the tracer agree on it.
//
// A prism room's faces are scene/prism_mesh.hpp's; the rest of this comment
// is about box rooms.
//
// Triangulation: each face is cut into a grid along lines shared by the whole
// room, on each axis the room's bounds and the edges of every hole, and emits
// the cells no hole covers, two triangles each. As all six faces use the same
// lines, neighbouring faces meet vertex to vertex along the room's edges, and
// a hole's portal front is built from the same grid points: walls and portal
// fronts form one closed surface with no T-junction, so a rasteriser leaves no
// cracks. The price is a few more triangles (a hole's lines also cut the other
// faces). Hole edges sit at the float values of the rectangle's coordinates.
//
// A face holding a rectangle that is not axis-aligned in it (beyond 1e-6 m) is
// cut into slabs instead (face_slabs.hpp): exact, but with T-junctions, and
// that portal keeps the plain front of its box corners.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "layout/layout.hpp"
#include "scene/mesh_writer.hpp"
#include "scene/portal_box.hpp"

namespace impossible::scene {

// Appends the faces of layout.rooms[room] in face order (layout/room_shape.hpp:
// a box room's six, a prism room's floor, ceiling and walls, prism_mesh.hpp),
// with the room's colours and checker. `room_portals` lists the room's portals
// (indices into layout.portals, ascending). For each portal p of them with a
// hole_face, sets fronts[p] (fronts has one entry per portal) to the front
// that matches the hole's edges. A face with a texture gets texture
// coordinates (FaceUv). Returns each face's index range, in face order
// (layout::face_count(room) of them).
std::vector<IndexRange> append_room_faces(MeshWriter& out, const layout::Layout& layout, int room,
                                          const std::vector<int>& room_portals,
                                          std::vector<std::optional<FrontGrid>>& fronts);

}  // namespace impossible::scene
