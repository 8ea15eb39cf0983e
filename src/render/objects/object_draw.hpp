// Internal to src/render: dynamic objects (moving props, hands, crossing
// objects) and volume portals drawn in the stencil recursion
// (instance_draw.cpp, object_draw.cpp; the frame's objects are placed by frame_objects.hpp).
#pragma once

#include "render/draw/draw_state.hpp"

namespace impossible::render {

// The program a draw of view.cell uses: the plain or material one, or the
// variant with `flags` (and kVolumes where the cell has volumes, unless
// view.outside_volumes).
const SceneProgram& cell_program(const DrawContext& ctx, const LevelView& view, unsigned flags = 0u);

// A level's colour pass over its cell: the cell's batches and its
// instances. In a cell with volumes, with culling (and
// FrameDesc::split_volume_draws), the plain variants draw the parts of the
// level's rectangles outside the volumes' screen bounds (four bands per
// eye) and the discarding VOLUMES variant only inside them; else the
// VOLUMES variant everywhere.
void draw_level_colour(const DrawContext& ctx, const LevelView& view, const Scissor& scissor);

// A batch's material uniforms and texture on a kMaterials program `m`.
void set_material(const DrawContext& ctx, const SceneProgram& m, const scene::DrawBatch& b);
bool has_material(const scene::DrawBatch& b);

// The instances placed in `cell` that the level's eyes may see, drawn in
// `view` (whose cell is `cell`, or holds a volume whose target is `cell`)
// with id cell + 1; `inside` as set_volume_uniforms's (instance_draw.cpp):
// every plain batch of every visible instance in one multi-draw, each
// command an instance's batch for both eyes with its per-instance record
// (instance_stream.hpp) as its base instance; batches with materials one
// draw each.
void draw_cell_instances(const DrawContext& ctx, const LevelView& view, const Scissor& scissor, int cell, int inside);

// Each volume of view.cell: its target room's batches and instances, shown
// only inside the volume, tinted.
void draw_volume_rooms(const DrawContext& ctx, const LevelView& view, const Scissor& scissor);

}  // namespace impossible::render
