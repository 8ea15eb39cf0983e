#include "render/objects/multi_draw.hpp"

#include <algorithm>

namespace impossible::render {

void begin_indirect_frame(IndirectDraws& draws) {
    if (!draws.buffer) draws.buffer = gl::create_buffer();
    draws.used = 0;
    draws.pending.clear();
}

int submit_indirect(gl::StateCache& state, IndirectDraws& draws) {
    const std::size_t n = draws.pending.size();
    if (n == 0) return 0;
    if (n == 1) {
        const IndirectDraw& d = draws.pending[0];
        glDrawElementsInstanced(GL_TRIANGLES, static_cast<GLsizei>(d.count), GL_UNSIGNED_INT,
                                reinterpret_cast<const void*>(static_cast<std::uintptr_t>(d.first_index) * 4),
                                static_cast<GLsizei>(d.instance_count));
        draws.pending.clear();
        return 1;
    }
    if (draws.used + n > draws.capacity) {
        // Re-specifying the store orphans the old one: commands already
        // submitted keep theirs.
        draws.capacity = std::max({2 * draws.capacity, draws.used + n, std::size_t{1024}});
        glNamedBufferData(draws.buffer.get(), static_cast<GLsizeiptr>(draws.capacity * sizeof(IndirectDraw)), nullptr,
                          GL_STREAM_DRAW);
        draws.used = 0;
    }
    const std::size_t offset = draws.used * sizeof(IndirectDraw);
    glNamedBufferSubData(draws.buffer.get(), static_cast<GLintptr>(offset),
                         static_cast<GLsizeiptr>(n * sizeof(IndirectDraw)), draws.pending.data());
    state.draw_indirect_buffer(draws.buffer.get());
    glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT, reinterpret_cast<const void*>(offset),
                                static_cast<GLsizei>(n), 0);
    draws.used += n;
    draws.pending.clear();
    return 1;
}

}  // namespace impossible::render
