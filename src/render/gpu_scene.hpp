// The scene's shared vertex and index arrays on the GPU, with one vertex array
// object describing scene::Vertex.
#pragma once

#include "gl/handles.hpp"
#include "scene/scene.hpp"

namespace impossible::render {

struct GpuScene {
    gl::Buffer vertices;
    gl::Buffer indices;
    gl::VertexArray vao;
};

GpuScene upload_scene(const scene::Scene& scene);

}  // namespace impossible::render
