// Internal to src/render: the per-instance data of dynamic objects
// (shaders/scene.vert.glsl, OBJECT_CUTS), read by the vertex shader from a
// float texture: each object mesh's vertices carry their mesh's index (a
// "slot", GpuScene::object_slots), and a level's records are written as a
// block indexed by slot, so that a draw of consecutive meshes' index ranges
// reads each vertex's own instance's record: the visible instances of a
// cell then draw as runs of the index buffer, as still props do.
#pragma once

#include <cstddef>
#include <vector>

#include "gl/handles.hpp"
#include "gl/state.hpp"

namespace impossible::render {

// One instance: the rigid map from its mesh's coordinates to the cell's
// (less the cell's origin), as three rows of a 3 × 4 matrix, and the two
// door planes that cut it, in the mesh's coordinates ((0, 0, 0, 1): none):
// five texels.
struct InstanceRecord {
    float model_rows[3][4];
    float cut_planes[2][4];
};
static_assert(sizeof(InstanceRecord) == 80);

inline constexpr int kRecordTexels = 5;     // RGBA32F texels a record
inline constexpr int kRecordsPerRow = 256;  // the texture's width: 1,280 texels
// The texture unit the records are read from (0, 1: portal textures; 2: a
// batch's texture; 3: shadow maps).
inline constexpr unsigned kInstanceRecordUnit = 4;
static_assert(kInstanceRecordUnit < static_cast<unsigned>(gl::kTextureUnits), "the state cache tracks this unit");
// The vertex attribute of the slot (after scene::Vertex's six), at binding 1.
inline constexpr unsigned kSlotAttribute = 6;
inline constexpr unsigned kSlotBinding = 1;

// The records of a frame: blocks written one after another (each from the
// start of a texture row) into one texture reused from frame to frame; a
// larger one replaces it when a frame needs more, and past the driver's
// largest texture the writing starts again from row 0 (GL orders the
// writes after the draws that read the rows before).
struct InstanceStream {
    gl::Texture texture;
    int rows = 0;                         // the texture's height
    int used_rows = 0;                    // rows written this frame
    std::vector<InstanceRecord> pending;  // the next block, indexed from 0
};

// Starts writing from the first row.
void begin_instance_frame(InstanceStream& stream);

// Writes the pending block and returns the index of its first record in
// the texture (a multiple of kRecordsPerRow); clears it. `state` learns of a
// texture replaced.
int write_instances(InstanceStream& stream, gl::StateCache& state);

}  // namespace impossible::render
