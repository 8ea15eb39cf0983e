// The faces of a prism room (layout-format.md, "Rooms of any shape") for the
// reference tracer: built from layout::face_frame, holes found again from the
// spec's rule, and intersected in double precision, front faces only, as a
// box room's faces are (intersect.hpp, hit_room_face). Internal to
// src/trace; see docs/tracer.md, "Rooms of any shape".
#pragma once

#include <limits>

#include "layout/room_shape.hpp"
#include "trace/intersect.hpp"
#include "trace/trace_scene.hpp"

namespace impossible::trace {

// A prism room's faces, in layout face order, without holes (add them with
// prism_hole_face).
PrismShape prism_shape(const layout::Room& room);

// Whether the portal's rectangle cuts a hole in the face: its normal points
// into the room (within 60° of the face's), all four corners lie within
// kHolePlaneTolerance of the face's plane and inside the face's outline (a
// sliver of the same tolerance outside counts as inside).
bool cuts_prism_hole(const layout::FaceFrame& face, const math::PortalRect& rect);

// The first face of the prism room (prism_shape's faces, whose frames it
// keeps: a face's frame costs a pass over the floor) in which the rectangle
// cuts a hole, or -1.
int prism_hole_face(const PrismShape& prism, const math::PortalRect& rect);

// Whether (x, z) lies in the floor polygon or within its tolerance of an edge.
bool in_prism_floor(const PrismShape& prism, double x, double z);

// The nearest front-facing face of a prism room along the ray that the clip
// plane keeps, nearer than t_limit: the first face in order at the smallest
// t. `portal` ≥ 0 where the hit lies in that portal's hole (as FaceHit).
struct PrismHit {
    int face = -1;  // -1: none
    double t = 0.0;
    int portal = -1;
};
PrismHit hit_prism_faces(const Scene& scene, const PrismShape& prism, const dvec3& origin, const dvec3& dir,
                         const ClipPlane& clip, double t_limit = std::numeric_limits<double>::infinity());

}  // namespace impossible::trace
