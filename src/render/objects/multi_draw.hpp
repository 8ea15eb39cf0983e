// Several index ranges of one draw state submitted in one call
// (glMultiDrawElementsIndirect), each with the stereo scheme's instances: the
// props a level sees are runs of the cell's index buffer with gaps where
// culled props lie, and one call replaces a draw per run.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "gl/handles.hpp"
#include "gl/state.hpp"
#include "scene/scene.hpp"

namespace impossible::render {

// GL's DrawElementsIndirectCommand.
struct IndirectDraw {
    std::uint32_t count = 0;
    std::uint32_t instance_count = 0;
    std::uint32_t first_index = 0;
    std::int32_t base_vertex = 0;
    std::uint32_t base_instance = 0;
};
static_assert(sizeof(IndirectDraw) == 20);

// The commands of a frame, written one after another into one buffer that
// is reused from frame to frame (grown, by re-specifying it, when a frame
// needs more).
struct IndirectDraws {
    gl::Buffer buffer;
    std::size_t capacity = 0;           // commands the buffer holds
    std::size_t used = 0;               // commands written this frame
    std::vector<IndirectDraw> pending;  // not yet submitted
};

// Starts writing the buffer from the beginning (made on first use).
void begin_indirect_frame(IndirectDraws& draws);

// Queues a range for both eyes' instances (`instances`: 2, or 1 in two-pass
// stereo).
inline void queue_range(IndirectDraws& draws, const scene::IndexRange& range, int instances) {
    if (range.count == 0) return;
    draws.pending.push_back({range.count, static_cast<std::uint32_t>(instances), range.first, 0, 0});
}

// Submits the queued ranges with the state bound now: nothing for none, one
// glDrawElementsInstanced for one, one glMultiDrawElementsIndirect for more,
// with the buffer bound as GL_DRAW_INDIRECT_BUFFER through the cache.
// Returns the number of GL draw calls made (0 or 1).
int submit_indirect(gl::StateCache& state, IndirectDraws& draws);

}  // namespace impossible::render
