// Per-object culling inside a cell: which props a level's eyes may see,
// tested against each eye's frustum narrowed to its rectangle and its clip
// plane, through the cell's bounding-volume hierarchy (scene::CellObjects).
// No GL: the result is the batches to draw.
#pragma once

#include <cstdint>
#include <vector>

#include "render/objects/box_faces.hpp"
#include "render/portals/view.hpp"
#include "scene/scene.hpp"

namespace impossible::render {

// Scratch space reused from frame to frame (no allocation once warm).
struct CullScratch {
    std::vector<int> visible;  // object indices
    std::vector<int> stack;    // tree nodes still to test
};

// The batches of every object whose bounds may be seen by an active eye with
// a non-empty rectangle, in the cell's order (scene::finish_cell), then the
// cell's surfaces, merged where they follow each other with the same state
// (so a level that sees every object draws exactly the cell's full batches).
// Conservative: an object is dropped only when its padded bounds lie wholly
// outside one of the eye's planes (the rectangle widened by `margin_px`
// pixels of an eye_width × eye_height image), for both eyes.
void visible_batches(const scene::CellObjects& cell, const LevelView& view, int eye_width, int eye_height,
                     double margin_px, CullScratch& scratch, std::vector<scene::DrawBatch>& out);

// A level's draw of part of a cell: a batch of the scene's index buffer, or
// (`faces`) a range of the frame's face stream (render/objects/box_faces.hpp).
struct VisibleDraw {
    scene::DrawBatch batch;
    bool faces = false;
};

// visible_batches, with each visible box prop's faces that the level's eyes
// may see (box_front_faces with `faces`) appended to
// `face_indices` instead of its batch: the same triangles in the same
// order, less back faces. Consecutive boxes make one range of the stream
// (relative to the start of face_indices, cleared first).
void visible_draws(const scene::CellObjects& cell, const LevelView& view, int eye_width, int eye_height,
                   double margin_px, const BoxFaceView& faces, CullScratch& scratch,
                   std::vector<std::uint32_t>& face_indices, std::vector<VisibleDraw>& out);

// The same test for objects that are not the cell's own (a frame's dynamic
// objects, object_draw.cpp): the indices into cell.objects, in increasing
// order, of those whose bounds an active eye may see; none without a tree.
void visible_objects(const scene::CellObjects& cell, const LevelView& view, int eye_width, int eye_height,
                     double margin_px, CullScratch& scratch, std::vector<int>& out);

// Whether a portal's box is hidden from an eye by one of the cell's
// occluders (scene::CellObjects::occluders): every corner of the box lies in
// the box's shadow, at least a millimetre behind the face that hides it.
// The points hidden by a convex box form a convex set, so the whole portal
// is then hidden; the eye must stand outside the box, and with a clip plane
// the box must lie wholly in front of it (clipped geometry hides nothing).
// Exact on the CPU: no query, no synchronisation.
bool hidden_by_occluder(const scene::CellObjects& cell, const EyeView& eye, const math::PortalRect& portal);

}  // namespace impossible::render
