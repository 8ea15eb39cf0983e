// Internal to src/render: the per-instance data of dynamic objects drawn
// many to a draw (shaders/scene.vert.glsl, OBJECT_CUTS): one record per
// instance in a vertex buffer that the instances' vertex array reads with a
// divisor of the stereo scheme's instances per object, so that both eyes of
// an object read the same record.
#pragma once

#include <cstddef>
#include <vector>

#include "gl/handles.hpp"

namespace impossible::render {

// One instance: the rigid map from its mesh's coordinates to the cell's
// (less the cell's origin), as three rows of a 3 × 4 matrix, and the two
// door planes that cut it, in the mesh's coordinates ((0, 0, 0, 1): none).
struct InstanceRecord {
    float model_rows[3][4];
    float cut_planes[2][4];
};
static_assert(sizeof(InstanceRecord) == 80);

// The vertex attributes the records feed (after scene::Vertex's six).
inline constexpr unsigned kInstanceFirstAttribute = 6;
// The vertex array binding of the records (the vertices' is 0).
inline constexpr unsigned kInstanceBinding = 1;

// The records of a frame, written one draw's after another into one buffer
// reused from frame to frame (re-specified, larger, when a frame needs more),
// as multi_draw.hpp's commands are.
struct InstanceStream {
    gl::Buffer buffer;
    std::size_t capacity = 0;             // records the buffer holds
    std::size_t used = 0;                 // records written this frame
    std::vector<InstanceRecord> pending;  // the next draw's, not yet written
};

// Starts writing the buffer from the beginning (made on first use).
void begin_instance_frame(InstanceStream& stream);

// Writes the pending records after those already written this frame and
// returns their byte offset in the buffer; clears them.
std::size_t write_instances(InstanceStream& stream);

// Describes the records' attributes in `vao` (binding kInstanceBinding).
void describe_instances(unsigned vao);

}  // namespace impossible::render
