// Uniform locations are checked once, when a program is built: every
// program of the renderer has every uniform its variant uses, and a name the
// program lacks (misspelt) is an error naming it and the shaders, not a
// location of -1 that a draw would set without effect.
#include <gtest/gtest.h>

#include "gl/context.hpp"
#include "gl/shader.hpp"
#include "render/programs/scene_program.hpp"

namespace impossible {
namespace {

TEST(UniformCheck, EveryProgramOfTheRendererHasItsUniforms) {
    Result<gl::Context> context = gl::create_context(gl::Backend::Egl);
    ASSERT_TRUE(context) << context.error();
    for (render::StereoMode mode :
         {render::StereoMode::ClipShift, render::StereoMode::ViewportIndex, render::StereoMode::TwoPass})
        for (bool materials : {false, true}) {
            Result<render::SceneProgram> p = render::build_scene_program(mode, materials);
            ASSERT_TRUE(p) << p.error();
            EXPECT_GE(p->checker_offset, 0);
            EXPECT_GE(p->cell_id, 0);
            EXPECT_EQ(p->single_eye >= 0, mode == render::StereoMode::TwoPass);
            EXPECT_EQ(p->textured >= 0, materials);
        }
    Result<render::SceneProgram> texture = render::build_portal_texture_program();
    ASSERT_TRUE(texture) << texture.error();
    EXPECT_GE(texture->target_size, 0);
    EXPECT_EQ(texture->cell_id, -1);  // not in its fragment shader: never set
    Result<render::ClearDepthProgram> clear = render::build_clear_depth_program();
    ASSERT_TRUE(clear) << clear.error();
    for (bool multisample : {false, true}) {
        Result<render::WindowBlendProgram> blend = render::build_window_blend_program(multisample);
        ASSERT_TRUE(blend) << blend.error();
    }
    Result<gl::Program> resolve = render::build_id_resolve_program(4);
    ASSERT_TRUE(resolve) << resolve.error();
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(UniformCheck, AMisspeltUniformFailsWithItsAndTheShadersNames) {
    Result<gl::Context> context = gl::create_context(gl::Backend::Egl);
    ASSERT_TRUE(context) << context.error();
    const std::vector<gl::ShaderSource> stages = {
        render::embedded_shader(GL_VERTEX_SHADER, "shaders/clear_depth.vert.glsl"),
        render::embedded_shader(GL_FRAGMENT_SHADER, "shaders/clear_depth.frag.glsl")};
    Result<gl::Program> program = gl::build_program(stages, "");
    ASSERT_TRUE(program) << program.error();

    gl::UniformLocations right(program->get(), gl::program_name(stages));
    EXPECT_GE(right.required("u_far_depth"), 0);
    EXPECT_TRUE(right.check());

    gl::UniformLocations wrong(program->get(), gl::program_name(stages));
    EXPECT_EQ(wrong.required("u_far_dept"), -1);
    EXPECT_GE(wrong.required("u_color"), 0);
    const Result<void> checked = wrong.check();
    ASSERT_FALSE(checked);
    EXPECT_NE(checked.error().find("'u_far_dept'"), std::string::npos) << checked.error();
    EXPECT_NE(checked.error().find("shaders/clear_depth.vert.glsl + shaders/clear_depth.frag.glsl"), std::string::npos)
        << checked.error();
    EXPECT_EQ(checked.error().find("u_color"), std::string::npos) << checked.error();

    // A uniform a variant may lack is looked up as optional: -1, no error.
    gl::UniformLocations lenient(program->get(), gl::program_name(stages));
    EXPECT_EQ(lenient.optional("u_far_dept"), -1);
    EXPECT_TRUE(lenient.check());
}

}  // namespace
}  // namespace impossible
