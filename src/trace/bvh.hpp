// The nearest of a room's glTF triangles, or of its prop boxes, along a ray:
// by a linear scan, or through a bounding-volume hierarchy that gives
// exactly the same answer.
//
// The tree (binned surface-area heuristic, after Wald, "On fast Construction
// of SAH-based Bounding Volume Hierarchies", 2007) is built once per prepared
// scene, in double precision, by one thread, so the same triangles always
// give the same tree. The query tests exactly the triangles the scan tests,
// with the same function (hit_triangle), and keeps the same one: the
// smallest t, and among equal t the lowest index, which is the first one the
// scan meets. Boxes are padded so that no triangle the scan would report is
// ever skipped (bvh.cpp). See docs/tracer.md, "Many triangles".
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "trace/intersect.hpp"
#include "trace/trace_scene.hpp"

namespace impossible::trace {

// The nearest triangle hit and its index in the room's list (-1: none).
struct TriangleHit {
    std::optional<SurfaceHit> hit;
    int index = -1;
};

// The first triangle, in order, among those hit (hit_triangle) with the
// smallest t, counting only hits with t < t_limit (the nearest hit found so
// far on other surfaces, which wins a tie). Allocates nothing.
// `materials` are those the triangles name (PropTriangle::material).
TriangleHit nearest_triangle_scan(const std::vector<PropTriangle>& triangles, std::span<const PropMaterial> materials,
                                  const dvec3& origin, const dvec3& dir, const ClipPlane& clip, double t_limit);

// Builds the tree over `triangles`, all but the slivers (bvh.cpp), which
// are listed apart; no nodes when nothing is left. Leaves
// hold at most kBvhLeafSize triangles, except below depth kBvhMaxDepth.
inline constexpr int kBvhLeafSize = 4;
inline constexpr int kBvhMaxDepth = 60;
Bvh build_bvh(const std::vector<PropTriangle>& triangles);

// The same answer as nearest_triangle_scan(triangles, …), through `bvh`,
// which must have been built over `triangles`. Allocates nothing.
TriangleHit nearest_triangle(const Bvh& bvh, const std::vector<PropTriangle>& triangles,
                             std::span<const PropMaterial> materials, const dvec3& origin, const dvec3& dir,
                             const ClipPlane& clip, double t_limit);

// The same for prop boxes (hit_prop_box), with the same rule: the first box
// in the list among those hit at the smallest t below t_limit. A room's
// boxes are offered after its faces, which win a tie (tracer.cpp).
struct BoxHit {
    std::optional<SurfaceHit> hit;
    int index = -1;
};
BoxHit nearest_box_scan(const std::vector<PropBox>& boxes, const dvec3& origin, const dvec3& dir, const ClipPlane& clip,
                        double t_limit);
Bvh build_box_bvh(const std::vector<PropBox>& boxes);
BoxHit nearest_box(const Bvh& bvh, const std::vector<PropBox>& boxes, const dvec3& origin, const dvec3& dir,
                   const ClipPlane& clip, double t_limit);

}  // namespace impossible::trace
