// Per-object culling's data (scene.hpp, CellObjects): each prop's bounds and
// a bounding-volume hierarchy over them per cell, so that a view tests the
// tree rather than every prop.
#pragma once

#include <cstdint>

#include "scene/scene.hpp"

namespace impossible::scene {

// The bounds of vertices [first_vertex, end) of the scene, in layout
// coordinates (the cell's origin added back), padded by a micrometre and a
// relative 1e-9 so that rounding never makes them too small.
void bound_object(const Scene& scene, std::uint32_t first_vertex, const glm::dvec3& origin, CellObject& object);

// Builds cell.nodes and cell.order over cell.objects: median splits on the
// longest axis of the objects' centres, at most kCullLeafSize per leaf.
// Deterministic.
inline constexpr int kCullLeafSize = 4;
void build_cull_tree(CellObjects& cell);

// The room's box props that can hide a portal: those with a face of at least
// kMinOccluderArea, the kMaxOccluders largest, each shrunk by a micrometre
// and a relative 1e-9 (as (min, max) in layout coordinates). Props marked in
// `skip` (the dynamic ones, walk/objects.hpp) are not occluders.
inline constexpr double kMinOccluderArea = 0.25;  // m²
inline constexpr std::size_t kMaxOccluders = 16;
std::vector<std::pair<glm::dvec3, glm::dvec3>> occluders_of(const layout::Room& room,
                                                            const std::vector<bool>& skip = {});

// Builds the tree, then renumbers the objects in its leaf order and moves
// the cell's indices (its surfaces' and then its objects', the last in
// scene.indices, as build_scene writes them) into objects in leaf order, then
// surfaces: objects a view sees together lie together and their draws merge,
// and props are drawn before the faces they stand on, which then fail the
// depth test where the props cover them. Returns the cell's batches in that
// order, merged.
std::vector<DrawBatch> finish_cell(Scene& scene, CellObjects& cell);

}  // namespace impossible::scene
