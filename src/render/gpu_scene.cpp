#include "render/gpu_scene.hpp"

#include <cstddef>

namespace impossible::render {

GpuScene upload_scene(const scene::Scene& scene) {
    GpuScene gpu;
    gpu.vertices = gl::create_buffer();
    gpu.indices = gl::create_buffer();
    gpu.vao = gl::create_vertex_array();
    // Zero-size buffers are valid GL but glNamedBufferStorage rejects size 0.
    glNamedBufferStorage(gpu.vertices.get(),
                         static_cast<GLsizeiptr>(scene.vertices.size() * sizeof(scene::Vertex) + 1),
                         nullptr, GL_DYNAMIC_STORAGE_BIT);
    glNamedBufferSubData(gpu.vertices.get(), 0,
                         static_cast<GLsizeiptr>(scene.vertices.size() * sizeof(scene::Vertex)),
                         scene.vertices.data());
    glNamedBufferStorage(gpu.indices.get(),
                         static_cast<GLsizeiptr>(scene.indices.size() * sizeof(std::uint32_t) + 4),
                         nullptr, GL_DYNAMIC_STORAGE_BIT);
    glNamedBufferSubData(gpu.indices.get(), 0,
                         static_cast<GLsizeiptr>(scene.indices.size() * sizeof(std::uint32_t)),
                         scene.indices.data());

    const GLuint vao = gpu.vao.get();
    glVertexArrayVertexBuffer(vao, 0, gpu.vertices.get(), 0, sizeof(scene::Vertex));
    glVertexArrayElementBuffer(vao, gpu.indices.get());
    auto attribute = [vao](GLuint index, GLint size, std::size_t offset) {
        glEnableVertexArrayAttrib(vao, index);
        glVertexArrayAttribFormat(vao, index, size, GL_FLOAT, GL_FALSE, static_cast<GLuint>(offset));
        glVertexArrayAttribBinding(vao, index, 0);
    };
    attribute(0, 3, offsetof(scene::Vertex, position));
    attribute(1, 3, offsetof(scene::Vertex, normal));
    attribute(2, 3, offsetof(scene::Vertex, color));
    attribute(3, 1, offsetof(scene::Vertex, checker));
    return gpu;
}

}  // namespace impossible::render
