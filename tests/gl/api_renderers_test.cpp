// Several renderers of the public API in one program, as the Python module
// makes one for each of its Renderer objects: the headless renderers of a
// thread share one context per backend (api/headless_share.hpp), each draws
// its own frame whichever drew last, and dropping one leaves the others
// working.
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <utility>

#include "impossible/impossible.hpp"

namespace impossible {
namespace {

api::Frame api_renderers_frame(api::Renderer& renderer) {
    api::View view;
    view.width = 64;
    view.height = 36;
    api::Expected<api::Frame> frame = renderer.render(view);
    EXPECT_TRUE(frame) << frame.error().message;
    return frame ? std::move(*frame) : api::Frame{};
}

api::Renderer api_renderers_make(const api::Layout& layout, api::Backend backend) {
    api::Expected<api::Renderer> made = api::Renderer::headless(layout, backend);
    if (!made) ADD_FAILURE() << made.error().message;
    return std::move(made).value();
}

void api_renderers_expect_same(const api::Frame& got, const api::Frame& want, const char* which) {
    EXPECT_EQ(got.width, want.width) << which;
    EXPECT_TRUE(got.rgb == want.rgb) << which;
    EXPECT_TRUE(got.ids == want.ids) << which;
}

TEST(ApiRenderers, EachDrawsItsOwnFrameInTheSharedContexts) {
    const api::Layout first_layout = api::Layout::builtin();
    api::Expected<api::Layout> loaded = api::Layout::load(IMPOSSIBLE_SOURCE_DIR "/layouts/mirror_hall.json");
    ASSERT_TRUE(loaded) << loaded.error().message;
    const api::Layout second_layout = *loaded;
    api::Frame first_alone, second_alone;
    {
        api::Renderer r = api_renderers_make(first_layout, api::Backend::Egl);
        first_alone = api_renderers_frame(r);
    }
    {
        api::Renderer r = api_renderers_make(second_layout, api::Backend::Egl);
        second_alone = api_renderers_frame(r);
    }
    ASSERT_FALSE(first_alone.rgb == second_alone.rgb);

    api::Renderer first = api_renderers_make(first_layout, api::Backend::Egl);
    std::optional<api::Renderer> second(api_renderers_make(second_layout, api::Backend::Egl));
    std::optional<api::Renderer> software(api_renderers_make(second_layout, api::Backend::OSMesa));
    for (int round = 0; round < 2; ++round) {
        api_renderers_expect_same(api_renderers_frame(first), first_alone, "first");
        api_renderers_expect_same(api_renderers_frame(*second), second_alone, "second");
        api_renderers_expect_same(api_renderers_frame(*software), second_alone, "osmesa");
    }
    second.reset();  // made current to free its objects, then gone
    api_renderers_expect_same(api_renderers_frame(first), first_alone, "first after the second");
    software.reset();
    api_renderers_expect_same(api_renderers_frame(first), first_alone, "first after both");
}

}  // namespace
}  // namespace impossible
