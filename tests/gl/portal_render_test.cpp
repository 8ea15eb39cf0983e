// Portals in the rasteriser: boxes seen by crossed eyes, the near plane,
// the recursion limit, culling, and rooms that overlap without bleeding.
#include <cstdio>
#include <set>

#include "gl/gl.hpp"
#include "gl/handles.hpp"

#include "gl_fixture.hpp"
#include "render/portals/view.hpp"

namespace impossible {
namespace {

using testing::id_at;

render::FrameDesc pose(const layout::Layout& l, const char* room, math::dvec3 p, double yaw, double pitch = 0) {
    render::FrameDesc f;
    f.head.position = p;
    f.head.yaw_deg = yaw;
    f.head.pitch_deg = pitch;
    f.room = layout::find_room(l, room);
    f.eye_width = 81;  // odd: the centre pixel looks along the view axis
    f.eye_height = 61;
    return f;
}

int centre_id(const image::Image& image, int eye) { return id_at(image, eye * 81 + 40, 30); }

// Default layout: hall_door at z = 0 faces +z (hall side), annex_door at the
// same place faces -z; the transfer matrix is the identity.
TEST(PortalBox, EyeBehindThePlaneInsideTheBoxSeesTheTargetRoom) {
    const layout::Layout l = testing::example_layout("default.json");
    // Head 2 mm in front of hall_door, looking -x: the right eye (at +z... no,
    // with yaw 90 the right axis is -z) stands 30 mm behind the plane.
    const image::Image image = testing::render_once(gl::Backend::Egl, l, pose(l, "hall", {0, 1.6, 0.002}, 90));
    EXPECT_EQ(centre_id(image, 0), 1) << "left eye, in front of the plane, sees the hall";
    EXPECT_EQ(centre_id(image, 1), 2) << "right eye, inside the box, sees the annex on the inner face";
    // Looking back out of the box (+z, towards the hall) the right eye sees
    // its own room through the open front.
    const image::Image back = testing::render_once(gl::Backend::Egl, l, pose(l, "hall", {0, 1.6, -0.01}, 180));
    EXPECT_EQ(centre_id(back, 0), 1);
    EXPECT_EQ(centre_id(back, 1), 1);
}

TEST(PortalBox, CrossedEyeWorksInTheOtherDirectionToo) {
    const layout::Layout l = testing::example_layout("default.json");
    // In the annex, 2 mm in front of annex_door (which faces -z), looking +x:
    // the right axis is +z, so the right eye is 30 mm behind annex_door.
    const image::Image image = testing::render_once(gl::Backend::Egl, l, pose(l, "annex", {0, 1.6, -0.002}, -90));
    EXPECT_EQ(centre_id(image, 0), 2) << "left eye sees the annex";
    EXPECT_EQ(centre_id(image, 1), 1) << "right eye, inside annex_door's box, sees the hall";
}

TEST(PortalBox, EyeCloserThanTheNearPlaneStillSeesTheTargetRoom) {
    const layout::Layout l = testing::example_layout("default.json");
    for (double d : {0.005, 0.001, 0.0001, 1e-6}) {
        const image::Image image = testing::render_once(gl::Backend::Egl, l, pose(l, "hall", {0, 1.6, d}, 0));
        std::set<int> ids(image.ids.begin(), image.ids.end());
        EXPECT_EQ(ids, std::set<int>{2}) << "head " << d << " m in front of the door";
    }
}

TEST(PortalBox, FreeStandingPortalIsInvisibleFromBehindAndBeside) {
    const layout::Layout l = testing::example_layout("default.json");
    // Behind hall_door (z < -depth), looking at its back: the hall only.
    image::Image image = testing::render_once(gl::Backend::Egl, l, pose(l, "hall", {0, 1.6, -1.5}, 180));
    EXPECT_EQ(std::set<int>(image.ids.begin(), image.ids.end()), std::set<int>{1});
    // Beside it, looking along its plane.
    image = testing::render_once(gl::Backend::Egl, l, pose(l, "hall", {1.5, 1.6, -0.1}, 90));
    EXPECT_EQ(std::set<int>(image.ids.begin(), image.ids.end()), std::set<int>{1});
}

TEST(PortalRecursion, RecursionLimitShowsTheFillAndId255) {
    const layout::Layout l = testing::example_layout("corridor.json");
    for (int depth : {0, 1, 3, 8}) {
        render::FrameDesc f = pose(l, "corridor", {0, 1.2, 3.5}, 0);
        f.max_depth = depth;
        render::FrameStats stats;
        const image::Image image = testing::render_once(gl::Backend::Egl, l, f, &stats);
        EXPECT_EQ(centre_id(image, 0), 255) << "depth " << depth;
        EXPECT_EQ(stats.max_level_reached, depth);
        EXPECT_EQ(stats.portal_passes_drawn, depth) << "one portal per level straight ahead";
        const std::uint8_t* c = testing::pixel(image, 40, 30);
        EXPECT_NEAR(c[0], 0.24 * 255, 1);
        EXPECT_NEAR(c[1], 0.22 * 255, 1);
        EXPECT_NEAR(c[2], 0.30 * 255, 1);
    }
}

TEST(PortalRecursion, DeeperLimitMovesTheFillFurtherAway) {
    const layout::Layout l = testing::example_layout("corridor.json");
    auto fill_pixels = [&](int depth) {
        render::FrameDesc f = pose(l, "corridor", {0, 1.2, 3.5}, 0);
        f.max_depth = depth;
        const image::Image image = testing::render_once(gl::Backend::Egl, l, f);
        return std::count(image.ids.begin(), image.ids.end(), 255);
    };
    const long d1 = fill_pixels(1), d2 = fill_pixels(2), d4 = fill_pixels(4);
    EXPECT_GT(d1, d2);
    EXPECT_GT(d2, d4);
    EXPECT_GT(d4, 0);
}

// Every layout from several poses: culling and scissors never change the image.
TEST(PortalCulling, CulledAndUnculledRendersAreEqual) {
    struct Case {
        const char* layout;
        const char* room;
        math::dvec3 p;
        double yaw, pitch;
    };
    const Case cases[] = {
        {"default.json", "hall", {0.3, 1.6, 1.6}, 8, 0},        {"default.json", "annex", {0.2, 1.5, -1.0}, 170, -5},
        {"four_rooms.json", "hall", {0, 1.6, 1.5}, 0, 0},       {"four_rooms.json", "library", {-1, 1.6, -1}, 150, 0},
        {"four_rooms.json", "hall", {1.8, 1.6, 1.8}, 40, 0},    {"tunnel.json", "yard", {0.6, 1.6, 2.6}, 8, 0},
        {"tunnel.json", "tunnel", {0, 1.6, -0.5}, 0, 0},        {"rotated.json", "hall", {0.2, 1.6, 1.6}, 5, 0},
        {"rotated.json", "gallery", {1.0, 1.6, 0.5}, 100, 0},   {"corridor.json", "corridor", {0.25, 1.6, 2}, 4, 0},
        {"corridor.json", "corridor", {0.5, 1.6, -3}, 170, 10}, {"loop.json", "red", {0, 1.6, -0.8}, 0, 0},
        {"loop.json", "green", {0.5, 1.6, -4}, -60, 0},
    };
    for (const Case& c : cases) {
        const layout::Layout l = testing::example_layout(c.layout);
        render::FrameDesc f = pose(l, c.room, c.p, c.yaw, c.pitch);
        f.eye_width = 160;
        f.eye_height = 90;
        render::FrameStats culled_stats, unculled_stats;
        const image::Image culled = testing::render_once(gl::Backend::Egl, l, f, &culled_stats);
        f.cull_portals = false;
        const image::Image unculled = testing::render_once(gl::Backend::Egl, l, f, &unculled_stats);
        EXPECT_EQ(testing::count_id_differences(culled, unculled), 0) << c.layout << " " << c.room;
        EXPECT_EQ(testing::count_colour_differences(culled, unculled, 1), 0) << c.layout << " " << c.room;
        EXPECT_LE(culled_stats.portal_passes_drawn, unculled_stats.portal_passes_drawn) << c.layout;
        f.cull_portals = true;
        f.occlusion_test = true;
        const image::Image tested = testing::render_once(gl::Backend::Egl, l, f);
        EXPECT_EQ(testing::count_id_differences(culled, tested), 0) << c.layout << " " << c.room;
        EXPECT_EQ(testing::count_colour_differences(culled, tested, 0), 0) << c.layout << " " << c.room;
    }
}

// A portal hidden behind a wall: without the test its 16 levels are drawn
// and rejected by the stencil; with it, conditional rendering drops them
// before any primitive is assembled. Counted with GL_PRIMITIVES_GENERATED;
// the image stays the same.
TEST(PortalCulling, OcclusionTestDropsSubtreesBehindAWall) {
    const layout::Layout l = testing::example_layout("corridor_wall.json");
    render::FrameDesc f = pose(l, "corridor", l.start.position, l.start.yaw_deg);
    f.max_depth = 16;
    // The wall is a box prop, which already hides the door on the CPU
    // (ObjectCulling.*); without that, the query must find it.
    f.cull_objects = false;
    Result<gl::Context> context = gl::create_context(gl::Backend::Egl);
    ASSERT_TRUE(context) << context.error();
    Result<render::Renderer> r = render::Renderer::create(context->state(), scene::build_scene(l));
    ASSERT_TRUE(r) << r.error();
    auto primitives = [&](bool occlusion_test, image::Image* image) {
        f.occlusion_test = occlusion_test;
        gl::Query q = gl::create_query(GL_PRIMITIVES_GENERATED);
        glBeginQuery(GL_PRIMITIVES_GENERATED, q.get());
        Result<render::RenderedFrame> result = r->render(f);
        glEndQuery(GL_PRIMITIVES_GENERATED);
        EXPECT_TRUE(result) << result.error();
        if (result) *image = result->image;
        GLuint64 n = 0;
        glGetQueryObjectui64v(q.get(), GL_QUERY_RESULT, &n);
        return n;
    };
    image::Image a, b;
    const GLuint64 plain = primitives(false, &a), tested = primitives(true, &b);
    std::printf("  primitives generated at depth 16 behind a wall: %llu without, %llu with the occlusion test\n",
                static_cast<unsigned long long>(plain), static_cast<unsigned long long>(tested));
    EXPECT_LT(tested * 4, plain) << "the hidden subtree is most of the work";
    EXPECT_EQ(testing::count_id_differences(a, b), 0);
    EXPECT_EQ(testing::count_colour_differences(a, b, 0), 0);
}

TEST(PortalCulling, FourRoomsCullsPortalsOutOfView) {
    const layout::Layout l = testing::example_layout("four_rooms.json");
    render::FrameStats stats;
    render::FrameDesc f = pose(l, "hall", {-1, 1.6, 1.5}, 0);
    f.fov_y_deg = 60;
    testing::render_once(gl::Backend::Egl, l, f, &stats);
    EXPECT_EQ(stats.portal_passes_drawn, 1) << "only the library door is in view";
    EXPECT_GE(stats.portal_passes_culled, 1);
}

// Rooms that overlap in space are separate cells: the hall shows none of the
// annex's props though they stand in the same place, and the annex seen
// through the door shows none of the hall's.
TEST(Cells, OverlappingRoomsNeverBleed) {
    const layout::Layout l = testing::example_layout("default.json");
    // From the hall, looking through the door at the spot of the annex's blue
    // box (x -0.5, z -1.3): the hall's own pixels must stay hall.
    render::FrameDesc f = pose(l, "hall", {0.8, 1.2, 1.5}, 25, -13);
    f.eye_width = 160;
    f.eye_height = 90;
    const image::Image image = testing::render_once(gl::Backend::Egl, l, f);
    // No blue-box colour (0.2, 0.35, 0.85 shaded) may appear outside pixels
    // whose id is the annex's.
    int blue_in_hall = 0, blue_in_annex = 0;
    for (size_t i = 0; i < image.ids.size(); ++i) {
        const std::uint8_t* c = &image.rgb[i * 3];
        const bool blue = c[2] > 100 && c[2] > c[0] * 2 && c[2] > c[1] + 40;
        if (!blue) continue;
        (image.ids[i] == 2 ? blue_in_annex : blue_in_hall) += 1;
    }
    EXPECT_EQ(blue_in_hall, 0);
    EXPECT_GT(blue_in_annex, 0) << "the annex's blue box is seen through the door";
}

}  // namespace
}  // namespace impossible

namespace impossible {
namespace {

// Render-to-texture portals (for comparison): at scale 1 the texture holds
// exactly the pixels stencil portals draw; smaller textures lose detail.
TEST(PortalTexture, FullScaleEqualsStencilPortalsAndSmallerScalesBlur) {
    for (const char* name : {"default.json", "corridor.json", "four_rooms.json"}) {
        const layout::Layout l = testing::example_layout(name);
        render::FrameDesc f =
            pose(l, layout::find_room(l, "hall") >= 0 ? "hall" : "corridor", l.start.position, l.start.yaw_deg);
        f.eye_width = 160;
        f.eye_height = 90;
        const image::Image stencil = testing::render_once(gl::Backend::Egl, l, f);
        f.portal_texture_scale = 1.0;
        render::FrameStats stats;
        const image::Image full = testing::render_once(gl::Backend::Egl, l, f, &stats);
        EXPECT_EQ(testing::count_id_differences(stencil, full), 0) << name;
        EXPECT_EQ(testing::count_colour_differences(stencil, full, 0), 0) << name;
        EXPECT_GE(stats.portal_passes_drawn, 1) << name;
        // The occlusion test with them: a texture's view shares the frame's
        // queries and its conditional rendering (which does not nest), and
        // the pixels stay the same.
        f.occlusion_test = true;
        const image::Image tested = testing::render_once(gl::Backend::Egl, l, f);
        EXPECT_EQ(testing::count_id_differences(stencil, tested), 0) << name;
        EXPECT_EQ(testing::count_colour_differences(stencil, tested, 0), 0) << name;
        f.occlusion_test = false;
        f.portal_texture_scale = 0.25;
        const image::Image quarter = testing::render_once(gl::Backend::Egl, l, f);
        EXPECT_GT(testing::count_colour_differences(stencil, quarter, 2), 0)
            << name << ": a quarter-size texture blurs";
    }
}

TEST(PortalTexture, NeedsClipShiftStereo) {
    const layout::Layout l = testing::example_layout("default.json");
    render::FrameDesc f = pose(l, "hall", l.start.position, l.start.yaw_deg);
    f.portal_texture_scale = 0.5;
    f.stereo = render::StereoMode::TwoPass;
    Result<gl::Context> context = gl::create_context(gl::Backend::Egl);
    ASSERT_TRUE(context) << context.error();
    Result<render::Renderer> r = render::Renderer::create(context->state(), scene::build_scene(l));
    ASSERT_TRUE(r) << r.error();
    Result<render::RenderedFrame> result = r->render(f);
    ASSERT_FALSE(result);
    EXPECT_NE(result.error().find("clip-shift"), std::string::npos);
}

// The rule that bounds the recursion (docs/bounded-work.md): a rectangle
// matters only if it holds a pixel centre, (2i + 1)/n - 1 in NDC.
TEST(PixelCentres, ARectangleMattersOnlyWithAPixelCentreInside) {
    using render::covers_pixel_centre;
    using render::NdcRect;
    // 4 x 2 pixels: centres at x = -0.75, -0.25, 0.25, 0.75 and y = -0.5, 0.5.
    EXPECT_TRUE(covers_pixel_centre(NdcRect{-1, -1, 1, 1}, 4, 2));
    EXPECT_TRUE(covers_pixel_centre(NdcRect{-0.3, 0.4, -0.2, 0.6}, 4, 2));
    EXPECT_FALSE(covers_pixel_centre(NdcRect{-0.2, 0.4, 0.2, 0.6}, 4, 2));    // between two columns
    EXPECT_FALSE(covers_pixel_centre(NdcRect{-0.3, -0.4, -0.2, 0.4}, 4, 2));  // between the rows
    EXPECT_FALSE(covers_pixel_centre(NdcRect{0.8, -1, 1, 1}, 4, 2));          // right of the last column
    EXPECT_FALSE(covers_pixel_centre(NdcRect::none(), 4, 2));
    // Multisampled, a rectangle between the centres may still hold samples.
    EXPECT_TRUE(covers_pixel_centre(NdcRect{-0.2, 0.4, 0.2, 0.6}, 4, 2, 4));
    EXPECT_FALSE(covers_pixel_centre(NdcRect::none(), 4, 2, 4));
    // Within 1/256 pixel counts (a vertex may snap that far); 1/100 does not.
    const double px = 2.0 / 4;
    EXPECT_TRUE(covers_pixel_centre(NdcRect{-0.25 + px / 300, 0, 0.1, 1}, 4, 2));
    EXPECT_FALSE(covers_pixel_centre(NdcRect{-0.25 + px / 100, 0, 0.1, 1}, 4, 2));
    EXPECT_TRUE(covers_pixel_centre(NdcRect{-0.5, 0, -0.25 - px / 300, 1}, 4, 2));
    EXPECT_FALSE(covers_pixel_centre(NdcRect{-0.5, 0, -0.25 - px / 100, 1}, 4, 2));
}

}  // namespace
}  // namespace impossible
