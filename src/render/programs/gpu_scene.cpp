#include "render/programs/gpu_scene.hpp"

#include <algorithm>
#include <cstddef>
#include <vector>

#include "render/objects/instance_stream.hpp"

namespace impossible::render {

namespace {

bool has_mipmaps(int min_filter) {
    namespace code = assets::sampler_code;
    return min_filter == code::kNearestMipmapNearest || min_filter == code::kLinearMipmapNearest ||
           min_filter == code::kNearestMipmapLinear || min_filter == code::kLinearMipmapLinear;
}

gl::Texture upload_texture(const scene::SceneTexture& t) {
    const image::Pixels& image = *t.image;
    int mip_levels = 1;
    if (has_mipmaps(t.sampler.min_filter))
        while ((std::max(image.width, image.height) >> mip_levels) > 0) ++mip_levels;
    gl::Texture texture = gl::create_texture(GL_TEXTURE_2D);
    const GLuint name = texture.get();
    glTextureStorage2D(name, mip_levels, GL_RGBA8, image.width, image.height);
    // Rows top first: row 0 is t = 0, as texture coordinates put the image's top there.
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureSubImage2D(name, 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.data.data());
    if (mip_levels > 1) glGenerateTextureMipmap(name);
    // The sampler codes are glTF's, which are OpenGL's enums.
    glTextureParameteri(name, GL_TEXTURE_MAG_FILTER, t.sampler.mag_filter);
    glTextureParameteri(name, GL_TEXTURE_MIN_FILTER, t.sampler.min_filter);
    glTextureParameteri(name, GL_TEXTURE_WRAP_S, t.sampler.wrap_s);
    glTextureParameteri(name, GL_TEXTURE_WRAP_T, t.sampler.wrap_t);
    return texture;
}

// scene::Vertex from `vertices`, indices from `indices`.
void describe_vertices(GLuint vao, GLuint vertices, GLuint indices) {
    glVertexArrayVertexBuffer(vao, 0, vertices, 0, sizeof(scene::Vertex));
    glVertexArrayElementBuffer(vao, indices);
    auto attribute = [vao](GLuint index, GLint size, std::size_t offset) {
        glEnableVertexArrayAttrib(vao, index);
        glVertexArrayAttribFormat(vao, index, size, GL_FLOAT, GL_FALSE, static_cast<GLuint>(offset));
        glVertexArrayAttribBinding(vao, index, 0);
    };
    attribute(0, 3, offsetof(scene::Vertex, position));
    attribute(1, 3, offsetof(scene::Vertex, normal));
    attribute(2, 3, offsetof(scene::Vertex, color));
    attribute(3, 1, offsetof(scene::Vertex, checker));
    attribute(4, 2, offsetof(scene::Vertex, uv));
    attribute(5, 1, offsetof(scene::Vertex, alpha));
}

// The slot attribute (kSlotAttribute) from `slots`, one float a vertex.
void describe_slots(GLuint vao, GLuint slots) {
    glVertexArrayVertexBuffer(vao, kSlotBinding, slots, 0, sizeof(float));
    glEnableVertexArrayAttrib(vao, kSlotAttribute);
    glVertexArrayAttribFormat(vao, kSlotAttribute, 1, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vao, kSlotAttribute, kSlotBinding);
}

void upload_slots(GLuint slots, const scene::Scene& scene) {
    std::vector<float> slot(scene.vertices.size() + 1, -1.0f);
    for (std::size_t m = 0; m < scene.object_meshes.size(); ++m)
        for (std::uint32_t v = scene.object_meshes[m].first_vertex; v < scene.object_meshes[m].vertex_end; ++v)
            slot[v] = static_cast<float>(m);
    glNamedBufferStorage(slots, static_cast<GLsizeiptr>(slot.size() * sizeof(float)), slot.data(), 0);
}

}  // namespace

GpuScene upload_scene(const scene::Scene& scene) {
    GpuScene gpu;
    gpu.vertices = gl::create_buffer();
    gpu.indices = gl::create_buffer();
    gpu.vao = gl::create_vertex_array();
    gpu.face_indices = gl::create_buffer();
    gpu.face_vao = gl::create_vertex_array();
    gpu.instance_vao = gl::create_vertex_array();
    gpu.instance_face_vao = gl::create_vertex_array();
    // The vertex arrays first: WebGL types a buffer by its first binding, and
    // an index buffer must be bound as one before its data comes
    // (gl/webgl.hpp).
    describe_vertices(gpu.vao.get(), gpu.vertices.get(), gpu.indices.get());
    describe_vertices(gpu.face_vao.get(), gpu.vertices.get(), gpu.face_indices.get());
    describe_vertices(gpu.instance_vao.get(), gpu.vertices.get(), gpu.indices.get());
    gpu.object_slots = gl::create_buffer();
    describe_slots(gpu.instance_vao.get(), gpu.object_slots.get());
    describe_vertices(gpu.instance_face_vao.get(), gpu.vertices.get(), gpu.face_indices.get());
    describe_slots(gpu.instance_face_vao.get(), gpu.object_slots.get());
    // Zero-size buffers are valid GL but glNamedBufferStorage rejects size 0.
    glNamedBufferStorage(gpu.vertices.get(), static_cast<GLsizeiptr>(scene.vertices.size() * sizeof(scene::Vertex) + 1),
                         nullptr, GL_DYNAMIC_STORAGE_BIT);
    glNamedBufferSubData(gpu.vertices.get(), 0, static_cast<GLsizeiptr>(scene.vertices.size() * sizeof(scene::Vertex)),
                         scene.vertices.data());
    glNamedBufferStorage(gpu.indices.get(), static_cast<GLsizeiptr>(scene.indices.size() * sizeof(std::uint32_t) + 4),
                         nullptr, GL_DYNAMIC_STORAGE_BIT);
    glNamedBufferSubData(gpu.indices.get(), 0, static_cast<GLsizeiptr>(scene.indices.size() * sizeof(std::uint32_t)),
                         scene.indices.data());

    upload_slots(gpu.object_slots.get(), scene);
    if (scene.lighting == layout::Lighting::Lights) {
        gpu.light_cells = gl::create_buffer();
        for (const GLuint vao : {gpu.vao.get(), gpu.face_vao.get()}) {
            glVertexArrayVertexBuffer(vao, kLightCellBinding, gpu.light_cells.get(), 0, 2 * sizeof(float));
            glEnableVertexArrayAttrib(vao, kLightCellAttribute);
            glVertexArrayAttribFormat(vao, kLightCellAttribute, 2, GL_FLOAT, GL_FALSE, 0);
            glVertexArrayAttribBinding(vao, kLightCellAttribute, kLightCellBinding);
        }
        const std::vector<float> none(2 * scene.vertices.size() + 2, -1.0f);
        glNamedBufferStorage(gpu.light_cells.get(), static_cast<GLsizeiptr>(none.size() * sizeof(float)), none.data(),
                             GL_DYNAMIC_STORAGE_BIT);
    }
    gpu.textures.reserve(scene.textures.size());
    for (const scene::SceneTexture& t : scene.textures) gpu.textures.push_back(upload_texture(t));
    return gpu;
}

}  // namespace impossible::render
