#include "gl/shader.hpp"

#include "gl/shader_profile.hpp"

namespace impossible::gl {
namespace {

std::string info_log(GLuint object, bool is_program) {
    GLint length = 0;
    if (is_program)
        glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
    else
        glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(length > 0 ? length : 0), '\0');
    if (length > 0) {
        if (is_program)
            glGetProgramInfoLog(object, length, nullptr, log.data());
        else
            glGetShaderInfoLog(object, length, nullptr, log.data());
    }
    while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
    return log;
}

}  // namespace

Result<Program> build_program(const std::vector<ShaderSource>& stages, const std::string& defines) {
    Program program(glCreateProgram());
    std::vector<Shader> shaders;
    std::vector<NamedBinding> bindings;  // the web profile's (gl/shader_profile.hpp)
    for (const ShaderSource& stage : stages) {
        const std::string text = profile_source(defines, stage.text, bindings);
        Shader shader(glCreateShader(stage.stage));
        const char* ptr = text.c_str();
        glShaderSource(shader.get(), 1, &ptr, nullptr);
        glCompileShader(shader.get());
        GLint ok = GL_FALSE;
        glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
        if (ok != GL_TRUE) return Error{stage.name + ": compile error: " + info_log(shader.get(), false)};
        glAttachShader(program.get(), shader.get());
        shaders.push_back(std::move(shader));
    }
    glLinkProgram(program.get());
    GLint ok = GL_FALSE;
    glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) return Error{program_name(stages) + ": link error: " + info_log(program.get(), true)};
    for (const Shader& s : shaders) glDetachShader(program.get(), s.get());
    for (const NamedBinding& b : bindings) {
        if (b.block) {
            const GLuint index = glGetUniformBlockIndex(program.get(), b.name.c_str());
            if (index != GL_INVALID_INDEX) glUniformBlockBinding(program.get(), index, static_cast<GLuint>(b.binding));
        } else {
            const GLint location = glGetUniformLocation(program.get(), b.name.c_str());
            if (location >= 0) glProgramUniform1i(program.get(), location, b.binding);
        }
    }
    return program;
}

std::string program_name(const std::vector<ShaderSource>& stages) {
    std::string names;
    for (const ShaderSource& s : stages) names += (names.empty() ? "" : " + ") + s.name;
    return names;
}

UniformLocations::UniformLocations(GLuint program, std::string shaders)
    : program_(program), shaders_(std::move(shaders)) {}

GLint UniformLocations::required(const char* name) {
    const GLint location = glGetUniformLocation(program_, name);
    if (location < 0) missing_ += (missing_.empty() ? "'" : ", '") + std::string(name) + "'";
    return location;
}

GLint UniformLocations::optional(const char* name) const { return glGetUniformLocation(program_, name); }

Result<void> UniformLocations::check() const {
    if (missing_.empty()) return {};
    return Error{shaders_ + ": the program has no uniform " + missing_ + " (misspelt, or not used by the shaders)"};
}

}  // namespace impossible::gl
