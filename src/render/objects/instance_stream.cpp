#include "render/objects/instance_stream.hpp"

#include <algorithm>
#include <cstddef>

namespace impossible::render {

void begin_instance_frame(InstanceStream& stream) {
    if (!stream.buffer) stream.buffer = gl::create_buffer();
    stream.used = 0;
    stream.pending.clear();
}

std::size_t write_instances(InstanceStream& stream) {
    const std::size_t n = stream.pending.size();
    if (stream.used + n > stream.capacity) {
        // Re-specifying the store orphans the old one: draws already made
        // keep theirs.
        stream.capacity = std::max({2 * stream.capacity, stream.used + n, std::size_t{256}});
        glNamedBufferData(stream.buffer.get(), static_cast<GLsizeiptr>(stream.capacity * sizeof(InstanceRecord)),
                          nullptr, GL_STREAM_DRAW);
        stream.used = 0;
    }
    const std::size_t offset = stream.used * sizeof(InstanceRecord);
    if (n > 0)
        glNamedBufferSubData(stream.buffer.get(), static_cast<GLintptr>(offset),
                             static_cast<GLsizeiptr>(n * sizeof(InstanceRecord)), stream.pending.data());
    stream.used += n;
    stream.pending.clear();
    return offset;
}

void describe_instances(unsigned vao) {
    for (unsigned k = 0; k < 5; ++k) {
        const GLuint index = kInstanceFirstAttribute + k;
        glEnableVertexArrayAttrib(vao, index);
        glVertexArrayAttribFormat(vao, index, 4, GL_FLOAT, GL_FALSE, static_cast<GLuint>(k * 4 * sizeof(float)));
        glVertexArrayAttribBinding(vao, index, kInstanceBinding);
    }
}

}  // namespace impossible::render
