// Back faces of box props left out on the CPU: a level draws, of each visible
// axis-aligned box prop (scene::CellObject::box_vertex), only the faces that
// some active eye of the level may see from their front, as indices written
// to a stream each frame (FaceStream) in the cell's order. A face left out is
// one the rasteriser's back-face culling (passes.hpp, Pass::Scene) would
// drop for every eye of the level, so the image is the same, with about half
// the boxes' triangles.
#pragma once

#include <cstdint>
#include <vector>

#include "gl/handles.hpp"
#include "render/portals/view.hpp"
#include "scene/scene.hpp"

namespace impossible::render {

// The six faces of a box prop as bits: bit 2 · axis + (1 for the + face).
inline constexpr unsigned kAllBoxFaces = 0x3f;

// How far behind a face's plane an eye must stand for the face to be left
// out: its image must be at least kBackFaceMinThicknessPx thick (llvmpipe
// snaps vertices to 1/256 pixel, and single-precision transforms err by
// less than 1/512 pixel, so the winding of a thinner sliver could flip),
// and at least kBackFaceMinDistance (plus float rounding of the coordinates).
inline constexpr double kBackFaceMinThicknessPx = 0.125;
inline constexpr double kBackFaceMinDistance = 1e-4;  // m

// The least number of pixels per radian anywhere in an eye's image of
// width × height pixels (its centre's, for a perspective projection): the
// view-projection's x and y rows, less their part along w, over w's norm.
double min_pixels_per_radian(const EyeView& eye, int width, int height);

// What box_front_faces needs of a level besides its eyes: per eye, the
// least pixel density (min_pixels_per_radian) and where the level's draws
// can make fragments (its rectangle widened by two pixels, within the
// image; the draws' clip distances take one); the eye image's size and
// samples per pixel.
struct BoxFaceView {
    double pixels_per_radian[2] = {0.0, 0.0};
    NdcRect reach[2];
    int width = 1, height = 1, samples = 1;
};
BoxFaceView box_face_view(const LevelView& view, int width, int height, int samples);

// The faces of a box [lo, hi] (layout coordinates, as the vertices lie) that
// some eye of `view` (active, with a rectangle) may draw a fragment of. A
// face is left out for an eye that stands behind its plane by more than the
// margins above (the rasteriser would cull it), or, with one sample per
// pixel, when the bound of its corners' images within the eye's reach holds
// no pixel centre (covers_pixel_centre: it would make no fragment; tested
// for boxes that look small, under kSmallBoxPx pixels across). Conservative:
// in doubt a face is kept (the rasteriser then culls or drops it itself).
inline constexpr double kSmallBoxPx = 8.0;
unsigned box_front_faces(const glm::dvec3& lo, const glm::dvec3& hi, const LevelView& view, const BoxFaceView& bf);

// The faces of the box [box_min, box_max] (exact, as the layout writes it)
// that lie in the exit plane (EyeView::exit_plane) of every active eye of
// `view`, within the
// tracer's tolerance. "What a pixel shows" keeps only what lies strictly in
// front of the plane, so they have no fragment in the image; a clip distance
// of 0, give or take float rounding, would keep some (a box standing on a
// floor seen from below through a trapdoor in it).
unsigned faces_in_clip_planes(const glm::dvec3& box_min, const glm::dvec3& box_max, const LevelView& view);

// Appends the indices of `faces` of the box whose 24 vertices start at
// `first_vertex` (scene/box_mesh.hpp), in append_box_prop's order.
void append_box_faces(std::uint32_t first_vertex, unsigned faces, std::vector<std::uint32_t>& out);

// The frame's face indices: one GL buffer written level after level at
// growing offsets (re-specified, orphaning the old store, when a frame needs
// more), drawn through a vertex array of its own (GpuScene::face_vao).
struct FaceStream {
    std::vector<std::uint32_t> pending;  // a level's indices, before upload
    std::size_t capacity = 0;            // indices the buffer holds
    std::size_t used = 0;                // indices written this frame
};

// Uploads `stream.pending` after what this frame wrote, into `buffer` (the
// element buffer of the face vertex array), and returns where it starts
// (an index offset); clears pending.
std::uint32_t upload_faces(FaceStream& stream, GLuint buffer);

}  // namespace impossible::render
