// A volume's target room as the volume can show it (layout-format.md,
// "Volume portals"): only the target's surfaces inside the volume are seen
// there, so a fragment of the target's cell outside the volume's box is
// discarded. Its draws leave out the triangles wholly outside the box, and
// draw the rest in pieces, each within the screen bounds of where its
// triangles meet the box (render/objects/object_draw.cpp, draw_volume_room):
// the same triangles in the same order as the whole cell, only fewer
// fragments to discard.
#pragma once

#include <cstddef>
#include <vector>

#include "scene/scene.hpp"

namespace impossible::scene {

// How far outside the box (a share of each half extent, and at least this
// many metres) a triangle still counts as meeting it: the fragment test's
// own tolerance is 1e-6, and a multisampled fragment's position may lie a
// little outside its triangle.
inline constexpr double kVolumeKeepShare = 0.02;
inline constexpr double kVolumeKeepMetres = 0.01;
// At most this many triangles make one piece.
inline constexpr std::uint32_t kVolumePieceTriangles = 64;
// At most this many pieces (draws) per volume.
inline constexpr std::size_t kVolumeMostPieces = 8;

// The pieces of cell `target`'s batches (its vertices relative to
// `target_origin`) that meet `volume`'s box grown as above, in order: runs of
// consecutive triangles in one plane (a face, at most kVolumePieceTriangles),
// then neighbours of one batch joined, those whose bounds grow least first,
// down to kVolumeMostPieces. A joined piece also draws the triangles between
// its runs, which meet no part of the box (their fragments are discarded, as
// in the whole cell's draw).
// `budget`: how many triangles the scene's volumes may still examine, less
// the target's here; a target of more is drawn whole (a piece per batch
// within the grown box's bounds), so that building a scene of many volumes
// over a large room stays proportional to the scene (a hostile layout's
// 20,000 volumes over 100,000 triangles would otherwise clip 2·10⁹).
inline constexpr std::size_t kVolumeTriangleBudget = 2'000'000;
std::vector<VolumePiece> volume_pieces(const Scene& scene, const std::vector<DrawBatch>& target,
                                       const glm::dvec3& target_origin, const layout::Volume& volume,
                                       std::size_t& budget);

}  // namespace impossible::scene
