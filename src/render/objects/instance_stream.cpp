#include "render/objects/instance_stream.hpp"

#include <algorithm>

namespace impossible::render {

void begin_instance_frame(InstanceStream& stream) {
    stream.used_rows = 0;
    stream.pending.clear();
}

int write_instances(InstanceStream& stream, gl::StateCache& state) {
    const int n = static_cast<int>(stream.pending.size());
    const int rows = std::max(1, (n + kRecordsPerRow - 1) / kRecordsPerRow);
    if (stream.used_rows + rows > stream.rows) {
        GLint most = 0;
        glGetIntegerv(GL_MAX_TEXTURE_SIZE, &most);
        const int wanted = std::max({2 * stream.rows, stream.used_rows + rows, 16});
        if (stream.rows < most) {
            if (stream.texture) state.deleting_texture(stream.texture.get());
            stream.rows = std::min(wanted, static_cast<int>(most));
            stream.texture = gl::create_texture(GL_TEXTURE_2D);
            glTextureStorage2D(stream.texture.get(), 1, GL_RGBA32F, kRecordTexels * kRecordsPerRow, stream.rows);
            glTextureParameteri(stream.texture.get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTextureParameteri(stream.texture.get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        }
        if (stream.used_rows + rows > stream.rows) stream.used_rows = 0;
    }
    const int first_row = stream.used_rows;
    // Whole rows past the first; one row as long as the block within it.
    const int width = n <= kRecordsPerRow ? std::max(n, 1) : kRecordsPerRow;
    stream.pending.resize(static_cast<size_t>(width) * static_cast<size_t>(rows));
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureSubImage2D(stream.texture.get(), 0, 0, first_row, kRecordTexels * width, rows, GL_RGBA, GL_FLOAT,
                        stream.pending.data());
    stream.used_rows += rows;
    stream.pending.clear();
    return first_row * kRecordsPerRow;
}

}  // namespace impossible::render
