// The light cache (render/lights/light_cache.hpp; docs/lighting.md, "The
// light cache"): a renderer's second frame at a light depth draws the light
// of still, flat surfaces from it. Against the first frame (exact, as
// without the cache) and the tracer: the same ids, the colour within the
// cache's interpolation.
#include <cstdio>
#include <string>

#include "crossing_rig.hpp"
#include "gl_fixture.hpp"
#include "image/compare.hpp"

namespace impossible {
namespace {

using testing::CrossingRig;

// The lamp hall with `n` point lights on a grid under each room's ceiling
// (bench's lights:N), or its own lamp for n = 0.
layout::Layout lamp_hall_with(int n) {
    layout::Layout l = testing::example_layout("lamp_hall.json");
    if (n == 0) return l;
    for (layout::Room& room : l.rooms) {
        room.lights.clear();
        const int side = n == 1 ? 1 : n == 8 ? 3 : 2;
        int placed = 0;
        for (int k = 0; placed < n; ++k, ++placed) {
            layout::Light light;
            const double fx = (k % side + 0.5) / side, fz = (k / side % side + 0.5) / side;
            light.position = {room.min.x + fx * (room.max.x - room.min.x), room.max.y - 0.3,
                              room.min.z + fz * (room.max.z - room.min.z) + 0.1 * (k / (side * side))};
            light.color = {1.0, 0.95, 0.9};
            light.intensity = 4.0 / n;
            room.lights.push_back(light);
        }
    }
    return l;
}

using View = testing::NamedView;

const View kViews[] = {
    {"bench view", "hall", {0.2, 1.7, 1.0}, 32.0, -31.0},
    {"start", "hall", {-1.6, 1.6, 1.2}, -70.0, -10.0},
    {"annex floor", "annex", {1.5, 1.6, 1.5}, -150.0, -40.0},
};

TEST(LightCacheRender, TheSecondFrameDrawsFromTheCacheWithTheFirstFramesIdsAndCloseColour) {
    // The lamp hall's own lamp and one light a room are below
    // kLightCacheMinImages: drawn exactly, never from the cache.
    for (const int n : {0, 1, 8}) {
        CrossingRig rig(lamp_hall_with(n));
        ASSERT_TRUE(rig.renderer);
        for (const View& v : kViews) {
            render::FrameDesc f = testing::frame_at(rig.layout, v.room, v.position, v.yaw, v.pitch);
            f.eye_width = 320;
            f.eye_height = 180;
            f.shadows = true;
            render::FrameStats exact_stats, cached_stats;
            f.light_cache = false;
            const image::Image exact = rig.render(f, &exact_stats);
            f.light_cache = true;
            (void)rig.render(f);
            const image::Image cached = rig.render(f, &cached_stats);
            const std::string what = std::string(v.what) + ", lights " + std::to_string(n);
            EXPECT_EQ(exact_stats.cached_levels, 0) << what;
            // The hall (16 images with 8 lights) is cached; the annex has a
            // door standing in it, whose box blocks its own lights.
            if (n == 8 && v.room == std::string("hall")) {
                EXPECT_GT(cached_stats.cached_levels, 0) << what;
            }
            if (n < 8) {
                EXPECT_EQ(cached_stats.cached_levels, 0) << what;
            }
            const image::Image traced = rig.trace(f);
            const image::Comparison to_exact = image::compare_pictures(cached, exact);
            const image::Comparison to_trace = image::compare_pictures(cached, traced);
            const image::Comparison exact_to_trace = image::compare_pictures(exact, traced);
            std::printf("  %-28s cached/exact %s\n  %-28s cached/trace %.2f dB, exact/trace %.2f dB\n", what.c_str(),
                        image::summary_line(to_exact).c_str(), "", to_trace.interior_psnr_db,
                        exact_to_trace.interior_psnr_db);
            EXPECT_EQ(exact.ids, cached.ids) << what;
            EXPECT_GE(to_exact.interior_psnr_db, 50.0) << what;
            EXPECT_EQ(to_trace.id_mismatches, 0) << what;
        }
    }
}

TEST(LightCacheRender, FramesThatAlternateShadowMapSizesDrawExactly) {
    // A cache is made for one map size; frames that alternate sizes (bench's
    // shadow-size sweep) draw exactly rather than remake it each frame, and
    // two frames in a row of one size draw from a cache made for it.
    CrossingRig rig(lamp_hall_with(8));
    ASSERT_TRUE(rig.renderer);
    render::FrameDesc f = testing::frame_at(rig.layout, "hall", {0.2, 1.7, 1.0}, 32.0, -31.0);
    f.shadows = true;
    int cached = 0;
    for (int k = 0; k < 4; ++k) {
        f.shadow_map_size = k % 2 == 0 ? 256 : 512;
        render::FrameStats stats;
        (void)rig.render(f, &stats);
        cached += stats.cached_levels;
    }
    EXPECT_EQ(cached, 0);
    render::FrameStats stats;
    (void)rig.render(f, &stats);
    EXPECT_GT(stats.cached_levels, 0);
}

TEST(LightCacheRender, EveryLitLayoutsSecondFrameKeepsItsIdsAndColour) {
    // Each lit example layout at its start, with its own lights and with 6
    // more under each room's ceiling (so that every room has images enough
    // to be cached where it can be: all but lit_flat's L-shaped hall, whose
    // path images meet its reflex walls).
    for (const char* name :
         {"lamp_hall.json", "lit_flat.json", "mirror_lamp.json", "spot_corridor.json", "tinted_window.json"}) {
        for (const bool more : {false, true}) {
            layout::Layout l = testing::example_layout(name);
            if (more)
                for (layout::Room& room : l.rooms)
                    for (int k = 0; k < 6; ++k) {
                        layout::Light light;
                        light.position = {glm::mix(room.min.x, room.max.x, (k % 3 + 0.5) / 3), room.max.y - 0.25,
                                          glm::mix(room.min.z, room.max.z, (k / 3 + 0.5) / 2)};
                        light.color = {0.9, 0.9, 1.0};
                        light.intensity = 0.4;
                        room.lights.push_back(light);
                    }
            CrossingRig rig(l);
            ASSERT_TRUE(rig.renderer);
            // Every stereo mode once; the others in clip-shift stereo.
            const int modes = more && name == std::string("tinted_window.json") ? 3 : 1;
            for (int mode = 0; mode < modes; ++mode) {
                render::FrameDesc f = testing::start_frame(rig.layout, -20.0);
                f.shadows = true;
                if (mode == 1) f.stereo = render::StereoMode::ViewportIndex;
                if (mode == 2) f.stereo = render::StereoMode::TwoPass;
                f.light_cache = false;
                const image::Image exact = rig.render(f);
                f.light_cache = true;
                (void)rig.render(f);
                render::FrameStats stats;
                const image::Image cached = rig.render(f, &stats);
                const std::string what = std::string(name) + (more ? " with 6 more lights" : "") + ", mode " +
                                         std::to_string(mode) + ", " + std::to_string(stats.cached_levels) +
                                         " cached levels";
                const image::Comparison cmp = image::compare_pictures(cached, exact);
                std::printf("  %-52s %s\n", what.c_str(), image::summary_line(cmp).c_str());
                EXPECT_EQ(cached.ids, exact.ids) << what;
                EXPECT_GE(cmp.interior_psnr_db, 50.0) << what;
            }
        }
    }
}

}  // namespace
}  // namespace impossible
