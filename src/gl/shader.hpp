// Compiling and linking GLSL with the info log shown: a failure names the
// shader file and carries the driver's message (which holds the line).
#pragma once

#include <string>
#include <vector>

#include "base/result.hpp"
#include "gl/handles.hpp"

namespace impossible::gl {

struct ShaderSource {
    GLenum stage;        // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER
    std::string name;    // e.g. "shaders/scene.vert.glsl", for messages
    std::string text;    // the source, without the #version line
};

// Compiles each stage as "#version 450 core" + `defines` + text and links.
Result<Program> build_program(const std::vector<ShaderSource>& stages, const std::string& defines);

}  // namespace impossible::gl
