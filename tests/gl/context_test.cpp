#include <gtest/gtest.h>

#include <type_traits>

#include "gl/context.hpp"
#include "gl/gl.hpp"
#include "gl/handles.hpp"

namespace impossible {
namespace {

class ContextTest : public ::testing::TestWithParam<gl::Backend> {};

TEST_P(ContextTest, CreatesACurrentGl45CoreContext) {
    Result<gl::Context> result = gl::create_context(GetParam());
    ASSERT_TRUE(result) << result.error();
    GLint major = 0, minor = 0, profile = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    EXPECT_GE(major * 10 + minor, 45) << result->version;
    EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
    // Entry points that libOSMesa does not export must still be loaded.
    EXPECT_NE(glad_glClipControl, nullptr);
    EXPECT_NE(glad_glCreateFramebuffers, nullptr);
    EXPECT_NE(glad_glGetQueryObjectui64v, nullptr);
    gl::Buffer buffer = gl::create_buffer();
    EXPECT_NE(buffer.get(), 0u);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_P(ContextTest, CanBeCreatedAgainAfterDestruction) {
    for (int i = 0; i < 3; ++i) {
        Result<gl::Context> result = gl::create_context(GetParam());
        ASSERT_TRUE(result) << result.error();
    }
}

INSTANTIATE_TEST_SUITE_P(Backends, ContextTest, ::testing::Values(gl::Backend::Egl, gl::Backend::OSMesa),
                         [](const auto& info) { return std::string(gl::backend_name(info.param)); });

TEST(Handles, AreMoveOnlyAndEmptyAfterMove) {
    static_assert(!std::is_copy_constructible_v<gl::Buffer>);
    static_assert(!std::is_copy_assignable_v<gl::Framebuffer>);
    static_assert(std::is_nothrow_move_constructible_v<gl::Program>);
    Result<gl::Context> result = gl::create_context(gl::Backend::Egl);
    ASSERT_TRUE(result) << result.error();
    gl::Buffer a = gl::create_buffer();
    const GLuint name = a.get();
    ASSERT_TRUE(glIsBuffer(name));
    gl::Buffer b = std::move(a);
    EXPECT_EQ(a.get(), 0u);
    EXPECT_FALSE(a);
    EXPECT_EQ(b.get(), name);
    b.reset();
    EXPECT_FALSE(glIsBuffer(name));
}

TEST(Context, BackendNamesRoundTrip) {
    EXPECT_EQ(gl::parse_backend("egl"), gl::Backend::Egl);
    EXPECT_EQ(gl::parse_backend("osmesa"), gl::Backend::OSMesa);
    EXPECT_FALSE(gl::parse_backend("glx"));
}

}  // namespace
}  // namespace impossible
