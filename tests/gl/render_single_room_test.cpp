// A closed room without portals: every pixel shows room 1, and a few colours
// match values computed by hand from the shading model.
#include <cmath>

#include "gl_fixture.hpp"

namespace impossible {
namespace {

using testing::id_at;
using testing::pixel;

using testing::expected_colour;

void expect_colour_near(const std::uint8_t* got, std::array<int, 3> want, const char* what) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(int(got[c]), want[c], 1) << what << " channel " << c;
}

render::FrameDesc centred_frame(double pitch_deg) {
    render::FrameDesc f;
    f.head.position = {0, 1.5, 0};
    f.head.pitch_deg = pitch_deg;
    f.eye_width = 65;  // odd: the centre pixel's ray is the view axis
    f.eye_height = 49;
    return f;
}

TEST(RenderSingleRoom, EveryPixelShowsTheRoom) {
    const layout::Layout l = testing::layout_from_text(testing::kSingleRoom);
    const image::Image image = testing::render_once(gl::Backend::Egl, l, centred_frame(10));
    ASSERT_EQ(image.width, 130);
    ASSERT_EQ(image.height, 49);
    for (std::uint8_t id : image.ids) ASSERT_EQ(id, 1);
}

TEST(RenderSingleRoom, CentreColoursMatchHandComputedShading) {
    const layout::Layout l = testing::layout_from_text(testing::kSingleRoom);
    // Straight ahead: the -z wall, normal (0, 0, 1).
    image::Image image = testing::render_once(gl::Backend::Egl, l, centred_frame(0));
    for (int eye = 0; eye < 2; ++eye)
        expect_colour_near(pixel(image, eye * 65 + 32, 24), expected_colour({0.9, 0.3, 0.1}, {0, 0, 1}), "-z wall");
    // Straight down: the floor, normal (0, 1, 0).
    image = testing::render_once(gl::Backend::Egl, l, centred_frame(-90));
    for (int eye = 0; eye < 2; ++eye)
        expect_colour_near(pixel(image, eye * 65 + 32, 24), expected_colour({0.2, 0.4, 0.8}, {0, 1, 0}), "floor");
    // Down onto the top of the prop box at (0, 1, -1.5).
    image = testing::render_once(gl::Backend::Egl, l, centred_frame(-std::atan(0.5 / 1.5) * 180.0 / M_PI));
    for (int eye = 0; eye < 2; ++eye)
        expect_colour_near(pixel(image, eye * 65 + 32, 24), expected_colour({0.1, 0.8, 0.2}, {0, 1, 0}), "prop top");
    // Straight up: the white ceiling, normal (0, -1, 0): ambient only.
    image = testing::render_once(gl::Backend::Egl, l, centred_frame(90));
    expect_colour_near(pixel(image, 32, 24), expected_colour({1, 1, 1}, {0, -1, 0}), "ceiling");
    EXPECT_EQ(id_at(image, 32, 24), 1);
}

TEST(RenderSingleRoom, LeftEyeIsOnTheLeft) {
    // A prop edge seen by both eyes appears further right in the left eye's
    // image (parallax): find the green prop's left edge on the centre row.
    const layout::Layout l = testing::layout_from_text(testing::kSingleRoom);
    render::FrameDesc f = centred_frame(-std::atan(0.5 / 1.5) * 180.0 / M_PI);
    f.ipd = 0.3;  // exaggerated so the shift is several pixels
    const image::Image image = testing::render_once(gl::Backend::Egl, l, f);
    auto first_green = [&](int eye) {
        for (int x = 0; x < 65; ++x)
            if (pixel(image, eye * 65 + x, 24)[1] > 150) return x;
        return -1;
    };
    const int left = first_green(0), right = first_green(1);
    ASSERT_GE(left, 0);
    ASSERT_GE(right, 0);
    EXPECT_GT(left, right + 2);
}

}  // namespace
}  // namespace impossible
