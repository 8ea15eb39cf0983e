#include "render/scene_program.hpp"

#include <cstdio>

#include "embedded.hpp"
#include "gl/shader.hpp"
#include "scene/shading.hpp"

namespace impossible::render {
namespace {

std::string shading_defines() {
    const glm::dvec3 l = scene::kLightDir;
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "#define LIGHT_DIR vec3(%.9g, %.9g, %.9g)\n#define AMBIENT %.9g\n"
                  "#define DIFFUSE %.9g\n#define CHECKER_DARK %.9g\n",
                  l.x, l.y, l.z, scene::kAmbient, scene::kDiffuse, scene::kCheckerDark);
    return buf;
}

}  // namespace

gl::ShaderSource embedded_shader(GLenum stage, const char* name) {
    return {stage, name, std::string(embedded::find(name))};
}

namespace {

SceneProgramResult link_scene_program(const char* fragment, const std::string& defines) {
    gl::ProgramResult built = gl::build_program(
        {embedded_shader(GL_VERTEX_SHADER, "shaders/scene.vert.glsl"), embedded_shader(GL_FRAGMENT_SHADER, fragment)},
        defines);
    SceneProgramResult out;
    if (!built.error.empty()) {
        out.error = built.error;
        return out;
    }
    SceneProgram& p = out.program;
    p.program = std::move(built.program);
    const GLuint name = p.program.get();
    p.view_proj = glGetUniformLocation(name, "u_view_proj");
    p.eye_rect = glGetUniformLocation(name, "u_eye_rect");
    p.clip_plane = glGetUniformLocation(name, "u_clip_plane");
    p.single_eye = glGetUniformLocation(name, "u_single_eye");
    p.cell_id = glGetUniformLocation(name, "u_cell_id");
    p.unshaded = glGetUniformLocation(name, "u_unshaded");
    p.target_size = glGetUniformLocation(name, "u_target_size");
    return out;
}

}  // namespace

SceneProgramResult build_scene_program(StereoMode mode) {
    std::string defines = shading_defines();
    if (mode == StereoMode::ViewportIndex) defines += "#define STEREO_VIEWPORT_INDEX\n";
    if (mode == StereoMode::TwoPass) defines += "#define STEREO_SINGLE_EYE\n";
    return link_scene_program("shaders/scene.frag.glsl", defines);
}

SceneProgramResult build_portal_texture_program() {
    SceneProgramResult out = link_scene_program("shaders/portal_texture.frag.glsl", "");
    if (out.error.empty()) {
        const GLuint name = out.program.program.get();
        glProgramUniform1i(name, glGetUniformLocation(name, "u_color_texture"), 0);
        glProgramUniform1i(name, glGetUniformLocation(name, "u_id_texture"), 1);
    }
    return out;
}

ClearDepthProgramResult build_clear_depth_program() {
    gl::ProgramResult built = gl::build_program(
        {embedded_shader(GL_VERTEX_SHADER, "shaders/clear_depth.vert.glsl"),
         embedded_shader(GL_FRAGMENT_SHADER, "shaders/clear_depth.frag.glsl")},
        "");
    ClearDepthProgramResult out;
    out.error = built.error;
    out.program.program = std::move(built.program);
    if (out.error.empty()) out.program.far_depth = glGetUniformLocation(out.program.program.get(), "u_far_depth");
    return out;
}

}  // namespace impossible::render
