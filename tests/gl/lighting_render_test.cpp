// The rasteriser's lit shader (layout-format.md, "Lights"; the LIGHTS variant
// of shaders/scene.frag.glsl) against a CPU evaluation of the same light
// images (lights::light_images) in double precision. The CPU side takes each
// pixel's surface from the tracer on the layout under "fixed" lighting (its
// point, normal, room, and base · dark as the fixed colour over the built-in
// light's factor), sums shading/lighting.hpp's contributions of the images
// whose segments pass their apertures and meet no blocker, and compares.
// Props cast no shadows here (no shadow maps): the CPU side ignores them too.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>

#include "cli/view_options.hpp"
#include "crossing_rig.hpp"
#include "gl_fixture.hpp"
#include "image/compare.hpp"
#include "lights/light_images.hpp"
#include "links/portal_links.hpp"
#include "render/lights/light_buffers.hpp"
#include "shading/lighting.hpp"
#include "shading/shading.hpp"
#include "trace/tracer.hpp"

namespace impossible {
namespace {

// A lamp hall: "hall" has a lamp near its east door into "annex" (turned by
// 90 degrees, on the same floor); the annex has no light of its own, and a
// spot light with a range in the hall's far corner. "vault" lies beyond the
// annex's closed south wall, with a lamp of its own, and no portal at all.
const char* kLampHall = R"({
  "format": "impossible-layout", "version": 1,
  "start": { "room": "hall", "position": [-1.3, 1.6, 0.9] },
  "rooms": [
    { "id": "hall", "min": [-2, 0, -2], "max": [2, 3, 2], "color": [0.80, 0.76, 0.68],
      "face_colors": { "floor": [0.55, 0.50, 0.44] }, "checker": 0.5,
      "props": [ { "box": { "min": [-0.2, 0, -1.4], "max": [0.7, 0.8, -0.6] }, "color": [0.70, 0.30, 0.20] } ] },
    { "id": "annex", "min": [-2, 0, -2], "max": [2, 2.7, 2], "color": [0.70, 0.80, 0.70],
      "face_colors": { "floor": [0.75, 0.72, 0.62] },
      "props": [ { "box": { "min": [-1.6, 0, 0.8], "max": [-0.9, 1.2, 1.5] }, "color": [0.30, 0.45, 0.80] } ] },
    { "id": "vault", "min": [-2, 0, 2], "max": [2, 2.7, 6], "color": [0.6, 0.6, 0.6] }
  ],
  "portals": [
    { "id": "hall_east", "room": "hall", "center": [2, 1.05, 0.2], "normal": [-1, 0, 0],
      "width": 1.0, "height": 2.1, "target": "annex_north" },
    { "id": "annex_north", "room": "annex", "center": [0.3, 1.05, -2], "normal": [0, 0, 1],
      "width": 1.0, "height": 2.1, "target": "hall_east" }
  ]
})";

layout::Light lit_point(glm::dvec3 position, glm::dvec3 color, double intensity) {
    layout::Light l;
    l.position = position;
    l.color = color;
    l.intensity = intensity;
    return l;
}

// The lamp hall under "lighting": "lights" at `depth`.
layout::Layout lit_lamp_hall(int depth) {
    layout::Layout l = testing::layout_from_text(kLampHall);
    l.lighting = layout::Lighting::Lights;
    l.light_depth = depth;
    l.rooms[0].ambient = {0.06, 0.06, 0.07};
    l.rooms[1].ambient = {0.04, 0.04, 0.05};
    l.rooms[2].ambient = {0.05, 0.05, 0.05};
    l.rooms[0].lights.push_back(lit_point({1.2, 2.3, 0.2}, {1.0, 0.92, 0.80}, 4.5));
    layout::Light spot = lit_point({-1.5, 2.6, -1.5}, {0.8, 0.9, 1.0}, 9.0);
    spot.range = 4.0;
    spot.spot = layout::Spot{glm::normalize(glm::dvec3(0.3, -1.0, 0.3)), 15.0, 40.0};
    l.rooms[0].lights.push_back(spot);
    l.rooms[2].lights.push_back(lit_point({0.0, 2.0, 4.0}, {1.0, 1.0, 1.0}, 50.0));
    return l;
}

// The same at light depth 2, with a lamp of the annex's own or without
// (then the annex is lit only through its door).
layout::Layout lit_lamp_hall_at_depth_2(bool annex_lamp) {
    layout::Layout l = lit_lamp_hall(2);
    if (annex_lamp) l.rooms[1].lights.push_back(lit_point({-1.0, 2.2, 1.0}, {0.9, 1.0, 0.9}, 3.0));
    return l;
}

// The lit colour of a surface point of room `room` with base · dark `bd`.
glm::dvec3 lit_expected(const layout::Layout& l, const std::vector<lights::RoomLights>& rooms, int room,
                        const glm::dvec3& bd, const glm::dvec3& p, const glm::dvec3& n) {
    glm::dvec3 sum(0.0);
    for (const lights::LightImage& image : rooms[static_cast<size_t>(room)].images) {
        if (!lights::segment_passes(image, p)) continue;
        const layout::Light& light =
            l.rooms[static_cast<size_t>(image.light_room)].lights[static_cast<size_t>(image.light)];
        const glm::dvec3 v = image.position - p;
        const double d = glm::length(v);
        const glm::dvec3 w = v / d;
        // spot_factor reads the light's own axis: the image's axis is the same
        // direction mapped into this room, so evaluate the cone with it.
        layout::Light mapped = light;
        if (mapped.spot) mapped.spot->direction = image.spot_direction;
        sum += shading::light_contribution(mapped, image.factor, n, w, d, w);
    }
    return shading::lit_color(bd, 1.0, rooms[static_cast<size_t>(room)].ambient, sum);
}

// The CPU frame: per pixel the tracer's surface under fixed lighting, lit as
// above; the id map is the tracer's.
image::Image lit_cpu_frame(const layout::Layout& lit, const render::FrameDesc& f) {
    layout::Layout fixed = lit;
    fixed.lighting = layout::Lighting::Fixed;
    const trace::Scene scene = trace::prepare_scene(fixed).value();
    const std::vector<lights::RoomLights> rooms =
        lights::light_images(lit, links::link_portals(lit), f.light_depth.value_or(lit.light_depth));
    const trace::TraceDesc desc = cli::trace_desc_for(f);
    const trace::FrameObjects objects = trace::place_frame_objects(scene, desc);
    image::Image out;
    out.width = 2 * f.eye_width;
    out.height = f.eye_height;
    out.rgb.assign(static_cast<size_t>(out.width * out.height * 3), 0);
    out.ids.assign(static_cast<size_t>(out.width * out.height), 0);
    for (int eye = 0; eye < 2; ++eye)
        for (int j = 0; j < f.eye_height; ++j)
            for (int i = 0; i < f.eye_width; ++i) {
                const trace::PixelRay ray = trace::pixel_ray(desc, eye, i, j);
                trace::RayLimits limits;
                limits.max_depth = f.max_depth;
                const trace::TraceHit hit = trace::trace_ray(scene, ray.origin, ray.dir, f.room, limits, objects);
                const size_t k = static_cast<size_t>(j * out.width + eye * f.eye_width + i);
                out.ids[k] = static_cast<std::uint8_t>(hit.id);
                glm::dvec3 colour = hit.color;
                if (hit.room >= 0 && hit.id != shading::kFillId) {
                    const double built_in =
                        shading::kAmbient + shading::kDiffuse * std::max(0.0, glm::dot(hit.normal, shading::kLightDir));
                    colour = lit_expected(lit, rooms, hit.room, hit.color / built_in, hit.point, hit.normal);
                }
                for (int c = 0; c < 3; ++c) out.rgb[3 * k + static_cast<size_t>(c)] = trace::to_byte(colour[c]);
            }
    return out;
}

using LightingRig = testing::CrossingRig;

render::FrameDesc lit_frame(const layout::Layout& l, const char* room, math::dvec3 position, double yaw, double pitch) {
    render::FrameDesc f;
    f.room = layout::find_room(l, room);
    f.head = {position, yaw, pitch, 0.0};
    f.eye_width = 160;
    f.eye_height = 96;
    f.shadows = false;  // props cast no shadows: the CPU side has none (see above)
    return f;
}

// 0 id mismatches and a colour PSNR of at least 50 dB inside the regions.
void expect_lit_agree(const image::Image& raster, const image::Image& cpu, const std::string& what) {
    ASSERT_FALSE(image::incomparable(raster, cpu)) << what;
    const image::Comparison cmp = image::compare_pictures(raster, cpu);
    std::printf("  %-48s %s\n", what.c_str(), image::summary_line(cmp).c_str());
    EXPECT_EQ(cmp.id_mismatches, 0) << what;
    EXPECT_GE(cmp.interior_psnr_db, 50.0) << what;
}

using LitView = testing::NamedView;

const LitView kLitViews[] = {
    {"the hall, lamp and spot", "hall", {-1.3, 1.6, 0.9}, -75.0, -15.0},
    {"the annex through the door", "hall", {-0.5, 1.6, 0.4}, -90.0, -20.0},
    {"the annex, lit through its door", "annex", {0.0, 1.6, 1.5}, 0.0, -25.0},
    {"down at the annex floor by the door", "annex", {0.3, 1.4, -1.0}, 0.0, -70.0},
};

TEST(LightingRender, MatchesTheLightImagesInEveryViewAndDepth) {
    for (const int depth : {0, 1, 2}) {
        LightingRig rig(lit_lamp_hall(depth));
        ASSERT_TRUE(rig.renderer);
        for (const LitView& v : kLitViews) {
            const render::FrameDesc f = lit_frame(rig.layout, v.room, v.position, v.yaw, v.pitch);
            expect_lit_agree(rig.render(f), lit_cpu_frame(rig.layout, f),
                             std::string(v.what) + ", light depth " + std::to_string(depth));
        }
    }
}

TEST(LightingRender, EachRoomDrawsWithTheLightLoopsItsImagesNeed) {
    // Issue 39: a room's own lights seen directly come first and skip the
    // path test; a room with only one kind of image draws with the variant
    // that has only that loop (llvmpipe pays for a loop it skips).
    for (const bool annex_lamp : {false, true}) {
        const layout::Layout l = lit_lamp_hall_at_depth_2(annex_lamp);
        LightingRig rig(l);
        ASSERT_TRUE(rig.renderer);
        const std::vector<lights::RoomLights> rooms = lights::light_images(l, links::link_portals(l), 2);
        const render::LightBuffers buffers =
            render::upload_light_images(rooms, l, std::vector<scene::CellOrigin>(rooms.size()), 2);
        // The hall: its lamp and spot, and with the annex's lamp its image
        // through the door; the annex: the hall's lamp through the door, and
        // its own; the vault: its lamp, no portal.
        EXPECT_EQ(buffers.direct[0], 2);
        // Every path image here passes the door alone: the one-aperture test.
        const unsigned single = render::kLightsSingleAperture;
        EXPECT_EQ(render::light_loop_flags(buffers, 0), annex_lamp ? single : render::kLightsNoPaths);
        EXPECT_EQ(buffers.direct[1], annex_lamp ? 1 : 0);
        EXPECT_EQ(render::light_loop_flags(buffers, 1), annex_lamp ? single : render::kLightsNoDirect | single);
        // The vault's lamp is a point light without a range: no spot or
        // range terms (the hall's spot and its image in the annex keep them).
        EXPECT_EQ(render::light_loop_flags(buffers, 2), render::kLightsNoPaths | render::kLightsPlainPoints);
        // Not split: each room's loops, with the lookups. Split: with maps,
        // each with and without the lookups (without maps, only without),
        // and a room with both kinds its direct loop alone too.
        const auto bit = [](unsigned flags) { return std::uint64_t{1} << render::light_loop_index(flags); };
        const auto no_lookups = [](std::uint64_t loops) {
            std::uint64_t out = 0u;
            for (unsigned f = 0; f < 64u; ++f)
                if (loops & (std::uint64_t{1} << f))
                    out |= std::uint64_t{1} << (f | render::light_loop_index(render::kLightsNoShadows));
            return out;
        };
        const std::uint64_t vault = bit(render::kLightsNoPaths | render::kLightsPlainPoints);
        const std::uint64_t unsplit =
            vault | (annex_lamp ? bit(single) : bit(render::kLightsNoPaths) | bit(render::kLightsNoDirect | single));
        const std::uint64_t split = unsplit | (annex_lamp ? bit(render::kLightsNoPaths) : 0u);
        EXPECT_EQ(render::light_loops_needed(buffers, true, false), unsplit);
        EXPECT_EQ(render::light_loops_needed(buffers, false, false), unsplit);
        EXPECT_EQ(render::light_loops_needed(buffers, true, true), split | no_lookups(split));
        EXPECT_EQ(render::light_loops_needed(buffers, false, true), no_lookups(split));
        if (annex_lamp) {  // without the vault's lamp, only the split needs the direct loop alone
            layout::Layout dark_vault = l;
            dark_vault.rooms[2].lights.clear();
            const std::vector<lights::RoomLights> r2 =
                lights::light_images(dark_vault, links::link_portals(dark_vault), 2);
            const render::LightBuffers b2 =
                render::upload_light_images(r2, dark_vault, std::vector<scene::CellOrigin>(r2.size()), 2);
            const std::uint64_t both = bit(single) | bit(render::kLightsNoPaths);
            EXPECT_EQ(render::light_loops_needed(b2, true, false), bit(single));
            EXPECT_EQ(render::light_loops_needed(b2, true, true), both | no_lookups(both));
        }
        for (const LitView& v : kLitViews) {
            const render::FrameDesc f = lit_frame(rig.layout, v.room, v.position, v.yaw, v.pitch);
            expect_lit_agree(rig.render(f), lit_cpu_frame(rig.layout, f),
                             std::string(v.what) + (annex_lamp ? ", with the annex's lamp" : ""));
        }
    }
}

TEST(LightingRender, PlainPointLightsDrawWithoutSpotAndRangeTermsAndTheSameImage) {
    // Issue 39: a room whose images are all point lights without a range
    // draws with the variant whose terms have neither factor
    // (kLightsPlainPoints). The same lights with a range of 10^6 m, whose
    // falloff rounds to exactly 1 in float, draw with the full term: the
    // same bytes, in every stereo mode.
    layout::Layout points = lit_lamp_hall_at_depth_2(true);
    for (layout::Room& room : points.rooms)
        for (layout::Light& light : room.lights) {
            light.spot.reset();
            light.range = 0.0;  // none
        }
    layout::Layout ranged = points;
    for (layout::Room& room : ranged.rooms)
        for (layout::Light& light : room.lights) light.range = 1e6;
    const auto plain_rooms = [](const layout::Layout& l) {
        const std::vector<lights::RoomLights> rooms = lights::light_images(l, links::link_portals(l), 2);
        const render::LightBuffers b =
            render::upload_light_images(rooms, l, std::vector<scene::CellOrigin>(rooms.size()), 2);
        int plain = 0;
        for (size_t c = 0; c < rooms.size(); ++c)
            plain += (render::light_loop_flags(b, static_cast<int>(c)) & render::kLightsPlainPoints) != 0;
        return plain;
    };
    LightingRig plain_rig(points), full_rig(ranged);  // a current context for the buffers
    ASSERT_TRUE(plain_rig.renderer && full_rig.renderer);
    EXPECT_EQ(plain_rooms(points), 3);
    EXPECT_EQ(plain_rooms(ranged), 0);
    for (const LitView& v : kLitViews)
        for (int mode = 0; mode < 3; ++mode) {
            render::FrameDesc f = lit_frame(points, v.room, v.position, v.yaw, v.pitch);
            if (mode == 1) f.stereo = render::StereoMode::ViewportIndex;
            if (mode == 2) f.stereo = render::StereoMode::TwoPass;
            const image::Image plain = plain_rig.render(f);
            const image::Image full = full_rig.render(f);
            EXPECT_EQ(plain.rgb, full.rgb) << v.what << ", mode " << mode;
            EXPECT_EQ(plain.ids, full.ids) << v.what << ", mode " << mode;
            if (mode == 0) expect_lit_agree(plain, lit_cpu_frame(points, f), std::string(v.what) + ", points only");
        }
}

TEST(LightingRender, OutsideTheLightPathsTheRoomDrawsWithoutThemAndTheSameImage) {
    // Issue 39: where no path image's lit region (lights::lit_region) is
    // seen, a lit room draws without the loop over its path images (or by
    // its ambient alone): the same image, in more draws.
    for (const bool annex_lamp : {false, true}) {
        const layout::Layout l = lit_lamp_hall_at_depth_2(annex_lamp);
        LightingRig rig(l);
        ASSERT_TRUE(rig.renderer);
        long more_draws = 0;
        for (const LitView& v : kLitViews) {
            // Each stereo mode, and multisampled (the scissor parts are whole
            // pixels, so every sample of a pixel is drawn by one part).
            for (int mode = 0; mode < 4; ++mode) {
                render::FrameDesc f = lit_frame(rig.layout, v.room, v.position, v.yaw, v.pitch);
                f.shadows = true;
                if (mode == 1) f.stereo = render::StereoMode::ViewportIndex;
                if (mode == 2) f.stereo = render::StereoMode::TwoPass;
                if (mode == 3) f.samples = 4;
                const std::string what = std::string(v.what) + ", mode " + std::to_string(mode);
                render::FrameStats split_stats, whole_stats;
                const image::Image split = rig.render(f, &split_stats);
                f.split_light_draws = false;
                const image::Image whole = rig.render(f, &whole_stats);
                EXPECT_EQ(split.rgb, whole.rgb) << what;
                EXPECT_EQ(split.ids, whole.ids) << what;
                EXPECT_GE(split_stats.draw_calls, whole_stats.draw_calls) << what;
                more_draws += split_stats.draw_calls - whole_stats.draw_calls;
            }
        }
        EXPECT_GT(more_draws, 0) << "the split never happened";
    }
}

TEST(LightingRender, NaiveLightsDropOnlyThePortalTests) {
    // Issue 39's baseline (FrameDesc::naive_lights, bench's lights:N/naive):
    // every image adds its term without the aperture and blocker tests. At
    // light depth 0 no image has a rectangle to test: the same frame, byte for
    // byte. Through the door at depth 2 the hall's lamp lights the whole
    // annex instead of the pool the door frame cuts: brighter (never darker)
    // where the exact test closes a path, the same ids.
    for (const int depth : {0, 2}) {
        LightingRig rig(lit_lamp_hall(depth));
        ASSERT_TRUE(rig.renderer);
        render::FrameDesc f = lit_frame(rig.layout, "annex", {0.0, 1.6, 1.5}, 0.0, -25.0);
        const image::Image exact = rig.render(f);
        f.naive_lights = true;
        const image::Image naive = rig.render(f);
        EXPECT_EQ(testing::count_id_differences(exact, naive), 0);
        int brighter = 0, darker = 0;
        for (size_t i = 0; i < exact.rgb.size(); ++i) {
            brighter += naive.rgb[i] > exact.rgb[i];
            darker += naive.rgb[i] < exact.rgb[i];
        }
        EXPECT_EQ(darker, 0) << "depth " << depth;
        if (depth == 0)
            EXPECT_EQ(brighter, 0);
        else
            EXPECT_GT(brighter, 1000);
    }
}

// An example layout lit: every room a lamp under its ceiling's centre.
layout::Layout lit_example(const char* name, int depth) {
    layout::Layout l = testing::example_layout(name);
    // Untinted mirrors: the CPU side sees tint · colour from the tracer and
    // cannot clamp before the tint as the rasteriser does.
    for (layout::Portal& p : l.portals)
        if (p.kind == layout::PortalKind::Mirror) p.tint = glm::dvec3(1.0);
    l.lighting = layout::Lighting::Lights;
    l.light_depth = depth;
    for (layout::Room& room : l.rooms) {
        const glm::dvec3 c = 0.5 * (room.min + room.max);
        room.lights.push_back(lit_point({c.x + 0.3, room.max.y - 0.4, c.z - 0.2}, {1.0, 0.95, 0.9}, 3.0));
    }
    return l;
}

TEST(LightingRender, LightsMovingPropsVolumeRoomsAndMirrors) {
    // sliding_box: a prop moving through a door (an OBJECT_CUTS instance, lit
    // in the room it is placed in); scanner_lab: a volume's target room, lit
    // by its own lamp; mirror_hall: the lamps' images in two mirrors.
    const char* names[] = {"sliding_box.json", "scanner_lab.json", "mirror_hall.json"};
    for (const char* name : names) {
        LightingRig rig(lit_example(name, 1));
        ASSERT_TRUE(rig.renderer);
        render::FrameDesc f = testing::start_frame(rig.layout, -15.0);
        f.shadows = false;
        for (const double time : {0.0, 2.5}) {
            f.time = time;
            expect_lit_agree(rig.render(f), lit_cpu_frame(rig.layout, f),
                             std::string(name) + " at " + std::to_string(time) + " s");
        }
    }
}

TEST(LightingRender, MatchesTheTracerWhereNoPropCastsAShadow) {
    // The lamp hall without its props, and the mirror hall's lamps (whose
    // props are left out too): the tracer's exact shadow rays against the
    // shader's aperture test, every view, light depths 0 to 2.
    layout::Layout hall = lit_lamp_hall(2);
    for (layout::Room& room : hall.rooms) room.props.clear();
    layout::Layout mirrors = lit_example("mirror_hall.json", 2);
    for (layout::Room& room : mirrors.rooms) room.props.clear();
    for (const int depth : {0, 1, 2}) {
        LightingRig rig(hall);
        ASSERT_TRUE(rig.renderer);
        for (const LitView& v : kLitViews) {
            render::FrameDesc f = lit_frame(rig.layout, v.room, v.position, v.yaw, v.pitch);
            f.light_depth = depth;
            expect_lit_agree(rig.render(f), trace::trace_frame(rig.layout, cli::trace_desc_for(f)).value(),
                             std::string("traced: ") + v.what + ", light depth " + std::to_string(depth));
        }
    }
    // Mirrors and windows (both of a window's branches), at several
    // recursion depths.
    for (const char* name : {"mirror_hall.json", "window_pair.json", "glass_gallery.json"}) {
        layout::Layout l = name == std::string("mirror_hall.json") ? mirrors : lit_example(name, 2);
        for (layout::Room& room : l.rooms) room.props.clear();
        LightingRig rig(l);
        ASSERT_TRUE(rig.renderer);
        for (const int max_depth : {1, 8}) {
            render::FrameDesc f;
            f.room = rig.layout.start.room;
            f.head = {rig.layout.start.position, rig.layout.start.yaw_deg, -15.0, 0.0};
            f.eye_width = 160;
            f.eye_height = 96;
            f.max_depth = max_depth;
            expect_lit_agree(rig.render(f), trace::trace_frame(rig.layout, cli::trace_desc_for(f)).value(),
                             std::string("traced: ") + name + ", depth " + std::to_string(max_depth));
        }
    }
}

TEST(LightingRender, PropsShadowsFromTheMapsAgainstTheTracer) {
    // The lamp hall with its props and their shadows (cube shadow maps): the
    // ids exactly, the colour approximately (the maps' texels at shadow
    // edges); the figures are printed.
    LightingRig rig(lit_lamp_hall(2));
    ASSERT_TRUE(rig.renderer);
    for (const LitView& v : kLitViews) {
        render::FrameDesc f = lit_frame(rig.layout, v.room, v.position, v.yaw, v.pitch);
        f.shadows = true;
        const image::Image traced = trace::trace_frame(rig.layout, cli::trace_desc_for(f)).value();
        const image::Comparison cmp = image::compare_pictures(rig.render(f), traced);
        std::printf("  shadows: %-39s %s\n", v.what, image::summary_line(cmp).c_str());
        EXPECT_EQ(cmp.id_mismatches, 0) << v.what;
        EXPECT_GE(cmp.interior_psnr_db, 30.0) << v.what;
    }
}

TEST(LightingRender, ManyImagesAreReadAsShaderStorage) {
    // 900 lamps in one room: their images (4500 vec4s) overflow the uniform
    // blocks (kLightUboVec4s), so the shader storage variant draws them.
    layout::Layout l = lit_lamp_hall(0);
    for (layout::Room& room : l.rooms) room.props.clear();
    l.rooms[0].lights.clear();
    for (int i = 0; i < 30; ++i)
        for (int k = 0; k < 30; ++k)
            l.rooms[0].lights.push_back(lit_point({-1.8 + 0.12 * i, 2.5, -1.8 + 0.12 * k}, {1.0, 0.9, 0.8}, 0.004));
    LightingRig rig(l);
    ASSERT_TRUE(rig.renderer);
    render::FrameDesc f = lit_frame(rig.layout, "hall", {-1.3, 1.6, 0.9}, -75.0, -15.0);
    f.eye_width = 48;
    f.eye_height = 32;
    render::FrameStats stats;
    expect_lit_agree(rig.render(f, &stats), lit_cpu_frame(rig.layout, f), "900 lamps in the hall");
    EXPECT_EQ(stats.light_images, 900);
}

TEST(LightingRender, LightDepthOfTheViewReplacesTheLayouts) {
    LightingRig rig(lit_lamp_hall(0));
    ASSERT_TRUE(rig.renderer);
    render::FrameDesc f = lit_frame(rig.layout, "annex", {0.3, 1.4, -1.0}, 0.0, -70.0);
    f.max_depth = 0;  // the annex alone (its images, not the hall's seen through its door)
    render::FrameStats at0, at1;
    const image::Image dark = rig.render(f, &at0);
    // No image reaches the annex at depth 0: its ambient alone, by the
    // LIGHTS_AMBIENT variant (issue 39: no loop over images at all).
    expect_lit_agree(dark, lit_cpu_frame(rig.layout, f), "the annex by its ambient alone");
    f.light_depth = 1;
    const image::Image lit = rig.render(f, &at1);
    expect_lit_agree(lit, lit_cpu_frame(rig.layout, f), "--light-depth 1 over the layout's 0");
    EXPECT_EQ(at0.light_images, 0);  // the annex has no light of its own
    EXPECT_GT(at1.light_images, 0);
    EXPECT_GT(testing::count_colour_differences(dark, lit, 8), 100);
}

TEST(LightingRender, ALightBehindAClosedWallAddsNoImages) {
    // The vault's lamp is beyond the annex's south wall, with no portal
    // between them: the annex's images are the hall's through the door only.
    LightingRig rig(lit_lamp_hall(2));
    ASSERT_TRUE(rig.renderer);
    render::FrameDesc f = lit_frame(rig.layout, "annex", {0.0, 1.6, 0.0}, 180.0, -20.0);
    f.max_depth = 0;  // the annex alone: its door shows the fill
    render::FrameStats stats;
    rig.render(f, &stats);
    const std::vector<lights::RoomLights> rooms = lights::light_images(rig.layout, links::link_portals(rig.layout), 2);
    for (const lights::LightImage& image : rooms[1].images) EXPECT_NE(image.light_room, 2);
    EXPECT_EQ(stats.light_images, static_cast<int>(rooms[1].images.size()));
    EXPECT_LE(stats.light_images, 2);  // at most the hall's two lights, through the door
    // The vault sees its own lamp and nothing of the others.
    f.room = 2;
    f.head.position = {0.0, 1.6, 4.5};
    rig.render(f, &stats);
    EXPECT_EQ(stats.light_images, 1);
}

TEST(LightingRender, StereoModesSamplesAndPortalTexturesAgree) {
    LightingRig rig(lit_lamp_hall(2));
    ASSERT_TRUE(rig.renderer);
    render::FrameDesc base = lit_frame(rig.layout, "hall", {-0.5, 1.6, 0.4}, -90.0, -20.0);
    base.shadows = true;  // the maps in every mode too
    const image::Image reference = rig.render(base);
    for (const render::StereoMode mode : {render::StereoMode::ViewportIndex, render::StereoMode::TwoPass}) {
        render::FrameDesc f = base;
        f.stereo = mode;
        const image::Image got = rig.render(f);
        EXPECT_EQ(testing::count_id_differences(got, reference), 0);
        EXPECT_EQ(testing::count_colour_differences(got, reference, 1), 0);
    }
    render::FrameDesc textured = base;
    textured.portal_texture_scale = 1.0;
    const image::Comparison via_texture = image::compare_pictures(rig.render(textured), reference);
    EXPECT_EQ(via_texture.id_mismatches, 0);
    EXPECT_GE(via_texture.interior_psnr_db, 40.0);
    render::FrameDesc multi = base;
    multi.samples = 4;
    const image::Comparison multisampled = image::compare_pictures(rig.render(multi), reference);
    EXPECT_EQ(multisampled.id_mismatches, 0);
    EXPECT_GE(multisampled.interior_psnr_db, 35.0);  // smoother edges of checks and light pools
}

TEST(LightingRender, FixedLayoutsCountNoImagesAndKeepTheBuiltInLight) {
    layout::Layout l = lit_lamp_hall(2);
    l.lighting = layout::Lighting::Fixed;
    LightingRig rig(l);
    ASSERT_TRUE(rig.renderer);
    const render::FrameDesc f = lit_frame(rig.layout, "hall", {-1.3, 1.6, 0.9}, -75.0, -15.0);
    render::FrameStats stats;
    const image::Image got = rig.render(f, &stats);
    EXPECT_EQ(stats.light_images, 0);
    const image::Comparison cmp = image::compare_pictures(got, trace::trace_frame(l, cli::trace_desc_for(f)).value());
    EXPECT_EQ(cmp.id_mismatches, 0);
    EXPECT_GE(cmp.interior_psnr_db, 35.0);
}

}  // namespace
}  // namespace impossible
