#include "render/scene_program.hpp"

#include <cstdio>

#include "embedded.hpp"
#include "gl/shader.hpp"
#include "render/gpu_scene.hpp"
#include "shading/shading.hpp"

namespace impossible::render {
namespace {

std::string shading_defines() {
    const glm::dvec3 l = shading::kLightDir;
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "#define LIGHT_DIR vec3(%.9g, %.9g, %.9g)\n#define AMBIENT %.9g\n"
                  "#define DIFFUSE %.9g\n#define CHECKER_DARK %.9g\n",
                  l.x, l.y, l.z, shading::kAmbient, shading::kDiffuse, shading::kCheckerDark);
    return buf;
}

}  // namespace

gl::ShaderSource embedded_shader(GLenum stage, const char* name) {
    return {stage, name, std::string(embedded::find(name))};
}

namespace {

Result<SceneProgram> link_scene_program(const char* fragment, const std::string& defines) {
    Result<gl::Program> built = gl::build_program(
        {embedded_shader(GL_VERTEX_SHADER, "shaders/scene.vert.glsl"), embedded_shader(GL_FRAGMENT_SHADER, fragment)},
        defines);
    if (!built) return Error{built.error()};
    SceneProgram p;
    p.program = std::move(*built);
    const GLuint name = p.program.get();
    p.view_proj = glGetUniformLocation(name, "u_view_proj");
    p.eye_rect = glGetUniformLocation(name, "u_eye_rect");
    p.clip_plane = glGetUniformLocation(name, "u_clip_plane");
    p.checker_offset = glGetUniformLocation(name, "u_checker_offset");
    p.single_eye = glGetUniformLocation(name, "u_single_eye");
    p.cell_id = glGetUniformLocation(name, "u_cell_id");
    p.unshaded = glGetUniformLocation(name, "u_unshaded");
    p.target_size = glGetUniformLocation(name, "u_target_size");
    p.textured = glGetUniformLocation(name, "u_textured");
    p.alpha_cutoff = glGetUniformLocation(name, "u_alpha_cutoff");
    p.level0 = glGetUniformLocation(name, "u_level0");
    glProgramUniform1i(name, glGetUniformLocation(name, "u_texture"), static_cast<GLint>(kSceneTextureUnit));
    glProgramUniform1f(name, p.alpha_cutoff, -1.0f);
    return p;
}

}  // namespace

Result<SceneProgram> build_scene_program(StereoMode mode, bool materials) {
    std::string defines = shading_defines();
    if (materials) defines += "#define MATERIALS\n";
    if (mode == StereoMode::ViewportIndex) defines += "#define STEREO_VIEWPORT_INDEX\n";
    if (mode == StereoMode::TwoPass) defines += "#define STEREO_SINGLE_EYE\n";
    return link_scene_program("shaders/scene.frag.glsl", defines);
}

Result<SceneProgram> build_portal_texture_program() {
    Result<SceneProgram> out = link_scene_program("shaders/portal_texture.frag.glsl", "");
    if (out) {
        const GLuint name = out->program.get();
        glProgramUniform1i(name, glGetUniformLocation(name, "u_color_texture"), 0);
        glProgramUniform1i(name, glGetUniformLocation(name, "u_id_texture"), 1);
    }
    return out;
}

Result<ClearDepthProgram> build_clear_depth_program() {
    Result<gl::Program> built = gl::build_program(
        {embedded_shader(GL_VERTEX_SHADER, "shaders/clear_depth.vert.glsl"),
         embedded_shader(GL_FRAGMENT_SHADER, "shaders/clear_depth.frag.glsl")},
        "");
    if (!built) return Error{built.error()};
    ClearDepthProgram out;
    out.program = std::move(*built);
    out.far_depth = glGetUniformLocation(out.program.get(), "u_far_depth");
    out.color = glGetUniformLocation(out.program.get(), "u_color");
    out.eye_quads = glGetUniformLocation(out.program.get(), "u_eye_quads");
    out.rects = glGetUniformLocation(out.program.get(), "u_rects");
    return out;
}

Result<WindowBlendProgram> build_window_blend_program(bool multisample) {
    Result<gl::Program> built = gl::build_program(
        {embedded_shader(GL_VERTEX_SHADER, "shaders/clear_depth.vert.glsl"),
         embedded_shader(GL_FRAGMENT_SHADER, "shaders/window_blend.frag.glsl")},
        multisample ? "#define SAVED_MULTISAMPLE\n" : "");
    if (!built) return Error{built.error()};
    WindowBlendProgram out;
    out.program = std::move(*built);
    const GLuint name = out.program.get();
    out.use_saved = glGetUniformLocation(name, "u_use_saved");
    out.scale = glGetUniformLocation(name, "u_scale");
    out.constant = glGetUniformLocation(name, "u_constant");
    glProgramUniform1i(name, glGetUniformLocation(name, "u_saved"), 0);
    return out;
}

}  // namespace impossible::render
