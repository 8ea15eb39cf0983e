// Compiling and linking GLSL with the info log shown: a failure names the
// shader file and carries the driver's message (which holds the line). The
// program's uniforms are looked up once, when it is built, and a missing one
// is an error then, naming it and the shaders.
#pragma once

#include <string>
#include <vector>

#include "base/result.hpp"
#include "gl/handles.hpp"

namespace impossible::gl {

struct ShaderSource {
    GLenum stage;      // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER
    std::string name;  // e.g. "shaders/scene.vert.glsl", for messages
    std::string text;  // the source, without the #version line
};

// Compiles each stage as "#version 450 core" + `defines` + text and links.
Result<Program> build_program(const std::vector<ShaderSource>& stages, const std::string& defines);

// The stages' names joined with " + ", for messages.
std::string program_name(const std::vector<ShaderSource>& stages);

// A program's uniform locations, looked up once when it is built. A uniform
// the program must have (required) but has not, being misspelt or gone from
// the shader, makes check() fail with its name and the shaders' names,
// instead of a draw setting location -1, which GL ignores without a word. A
// uniform that the GLSL compiler may optimise out of this variant of the
// shaders, because the variant does not use it, is looked up with optional()
// and may stay -1: setting it then does nothing, which is right for the
// variant.
class UniformLocations {
public:
    UniformLocations(GLuint program, std::string shaders);
    GLint required(const char* name);
    GLint optional(const char* name) const;
    // The required uniforms that are missing, as an error.
    Result<void> check() const;

private:
    GLuint program_;
    std::string shaders_;
    std::string missing_;
};

}  // namespace impossible::gl
