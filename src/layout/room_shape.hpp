// The shape of a room as a list of faces (layout-format.md, "Rooms" and
// "Rooms of any shape"): a box room is the six-face case, a prism room has a
// floor, a ceiling and one wall per edge of its floor polygon. Pure geometry
// in double precision; the loader, the rasteriser's meshes, the tracer, the
// walker and the designer tools all read rooms through it.
#pragma once

#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "layout/layout.hpp"
#include "math/polygon.hpp"

namespace impossible::layout {

inline bool is_prism(const Room& room) { return !room.floor.empty(); }

// 0 for a box room (its four sides are faces 2..5, not walls).
int wall_count(const Room& room);

// kFaceCount for a box room, 2 + wall_count for a prism room.
int face_count(const Room& room);

// Face 2 + i of a prism room; -1 for floor and ceiling and for a box room.
inline int wall_of_face(const Room& room, int face) { return is_prism(room) && face >= 2 ? face - 2 : -1; }

// A face's name as a layout file writes it: "floor", "ceiling", "-x" … for
// a box, "wall0", "wall1" … for a prism's walls.
std::string face_name(const Room& room, int face);

// The floor outline: a prism's polygon, or a box room's rectangle (x, z),
// counter-clockwise in (x, z) (math::signed_area > 0) in both cases. A
// prism's corners keep their file order when it is counter-clockwise and are
// reversed otherwise, so corner k here is not always corner k of the file.
math::Polygon2 floor_outline(const Room& room);

// Whether the floor outline is convex (a box room always is). Collinear
// corners count as convex.
bool floor_convex(const Room& room);

// A planar face of a room: `origin` + s · s_axis + t · t_axis for the face's
// 2D points (s, t). `normal` is unit and points into the room; s_axis,
// t_axis and normal are orthonormal with s_axis × t_axis = normal, so s runs
// to the right and t up for a viewer inside the room facing the face, and
// `outline` (the face's polygon in (s, t), without holes) is counter-
// clockwise (math::signed_area > 0).
//
//   floor:    s = x,  t = -z, origin (0, y0, 0)
//   ceiling:  s = -x, t = -z, origin (0, y1, 0)
//   wall i:   s along the wall (from corner i towards the viewer's right),
//             t = y, origin = corner i at y = 0
//   box side: as a wall, origin = the world origin's foot on the plane
struct FaceFrame {
    glm::dvec3 origin{0.0};
    glm::dvec3 s_axis{1.0, 0.0, 0.0};
    glm::dvec3 t_axis{0.0, 1.0, 0.0};
    glm::dvec3 normal{0.0, 0.0, 1.0};
    math::Polygon2 outline;
};

FaceFrame face_frame(const Room& room, int face);

// A point's (s, t) in a face's frame, and back.
glm::dvec2 to_face(const FaceFrame& frame, const glm::dvec3& p);
glm::dvec3 from_face(const FaceFrame& frame, const glm::dvec2& st);

// Wall i of a prism room: from file corner i to corner i + 1 (the last to the
// first), with the unit normal into the room.
struct Wall {
    glm::dvec2 a{0.0};  // corner i, (x, z)
    glm::dvec2 b{0.0};  // corner i + 1, (x, z)
    glm::dvec2 inward{0.0};
};
Wall wall(const Room& room, int index);

// The walls of a prism room that a straight segment between two points of
// the room can cross: those with a floor corner more than 1e-9 m (scaled
// by the floor's size) behind their line. None in a convex room or a box
// room; in an L the two walls of its reflex corner. A light's shadow ray
// meets these (lights::LightImage's blockers); no other wall can stop it.
std::vector<int> crossable_walls(const Room& room);

// Texture coordinates on a prism's wall, in tiles (layout-format.md, "Rooms
// of any shape"): s = distance from corner i towards the right of a viewer
// inside facing the wall, t = -y, both divided by `size`.
glm::dvec2 wall_uv(const Room& room, int wall_index, const glm::dvec3& p, double size);

// Whether the room holds the point: its box, or its prism (inside the floor
// polygon, edges included, and y0 <= y <= y1), within `tolerance` metres.
bool room_contains(const Room& room, const glm::dvec3& p, double tolerance = 0.0);

// Floor area in m² (the polygon's, or the box's x × z).
double floor_area(const Room& room);

}  // namespace impossible::layout
