// The scene's shared vertex and index arrays on the GPU, with one vertex array
// object describing scene::Vertex, and the scene's textures.
#pragma once

#include <vector>

#include "gl/handles.hpp"
#include "scene/scene.hpp"

namespace impossible::render {

// The texture unit the scene shader reads a batch's texture from (0 and 1 are
// the render-to-texture portals').
inline constexpr GLuint kSceneTextureUnit = 2;

struct GpuScene {
    gl::Buffer vertices;
    gl::Buffer indices;
    gl::VertexArray vao;
    // The same vertices with the frame's face stream as element buffer
    // (render/objects/box_faces.hpp): a buffer of no size until a frame writes it.
    gl::Buffer face_indices;
    gl::VertexArray face_vao;
    // The same vertices and indices with each vertex's object mesh (its
    // "slot", a float: the index into Scene::object_meshes, -1 for a cell's
    // vertex) at binding 1, for the dynamic objects' draws
    // (render/objects/instance_stream.hpp).
    gl::Buffer object_slots;
    gl::VertexArray instance_vao;
    gl::VertexArray instance_face_vao;  // the same with the face stream as element buffer
    std::vector<gl::Texture> textures;  // per scene::Scene::textures, with their mipmaps
    // A lit layout's: each vertex's place in the light cache's atlas (a
    // vec2, (-1, -1) until the cache is built: render/lights/light_cache.hpp)
    // at kLightCellBinding of vao and face_vao, attribute kLightCellAttribute.
    gl::Buffer light_cells;
};

inline constexpr unsigned kLightCellAttribute = 7;
inline constexpr unsigned kLightCellBinding = 2;

// Uploads the vertices, indices and textures. Textures keep the sampler's
// filters and wrap modes; a minification filter with mipmaps gets a full
// chain made by glGenerateTextureMipmap.
GpuScene upload_scene(const scene::Scene& scene);

}  // namespace impossible::render
