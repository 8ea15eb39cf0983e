// Real glTF lamps (issue 38 §1) in both renderers: a lamp whose shade and
// pane are alphaMode BLEND, alpha-tested at 0.5 (or opaque under "blend":
// "opaque"), and the exposure at ±2 EV on the lamp hall, against the tracer:
// 0 id mismatches and at least 40 dB of interior PSNR, the goal of lit
// layouts whose props cast shadows. Prints the figures.
#include <cstdio>

#include "cli/view_options.hpp"
#include "common/lamp_model.hpp"
#include "common/temp_dir.hpp"
#include "gl_fixture.hpp"
#include "image/compare.hpp"
#include "trace/tracer.hpp"

namespace impossible {
namespace {

// A lit 4 × 3 × 4 m room with the lamp at its centre and a lamp of its own
// behind the head; `fields` are added to the lamp's prop.
layout::Layout lamp_room(const std::string& fields) {
    const std::string model = test::temp_path("lamps_render_lamp.gltf").string();
    test::write_lamp_model(model);
    return testing::layout_from_text(R"({
      "format": "impossible-layout", "version": 1, "lighting": "lights",
      "start": { "room": "r", "position": [0, 1.3, 1.6] },
      "rooms": [ { "id": "r", "min": [-2, 0, -2], "max": [2, 3, 2], "color": [0.7, 0.7, 0.7], "checker": 0.5,
                   "ambient": [0.15, 0.15, 0.15],
                   "lights": [ { "position": [0.5, 2.5, 1.8], "intensity": 2 } ],
                   "props": [ { "gltf": ")" +
                                     model + R"(", "position": [0, 0, 0])" + fields + R"( } ] } ] })");
}

render::FrameDesc lamp_frame() {
    render::FrameDesc f;
    f.head = {{0.2, 1.3, 1.6}, 5, -5, 0};
    f.eye_width = 200;
    f.eye_height = 150;
    return f;
}

image::Comparison against_tracer(const layout::Layout& l, const render::FrameDesc& f, const char* what) {
    const image::Image raster = testing::render_once(gl::Backend::Egl, l, f);
    const image::Image traced = trace::trace_frame(l, cli::trace_desc_for(f)).value();
    EXPECT_FALSE(image::incomparable(raster, traced)) << what;
    const image::Comparison cmp = image::compare_pictures(raster, traced);
    std::printf("  %-44s %s\n", what, image::summary_line(cmp).c_str());
    return cmp;
}

TEST(LampsRender, ABlendLampAgreesWithTheTracerMaskedOrOpaque) {
    const layout::Layout masked = lamp_room("");
    ASSERT_EQ(masked.rooms.size(), 1u);
    ASSERT_EQ(masked.rooms[0].lights.size(), 2u);  // the written one and the bulb
    const image::Comparison cmp = against_tracer(masked, lamp_frame(), "BLEND lamp, alpha-tested at 0.5");
    EXPECT_EQ(cmp.id_mismatches, 0);
    EXPECT_GE(cmp.interior_psnr_db, 40.0);
    const layout::Layout opaque = lamp_room(R"(, "blend": "opaque")");
    const image::Comparison same = against_tracer(opaque, lamp_frame(), "BLEND lamp, \"blend\": \"opaque\"");
    EXPECT_EQ(same.id_mismatches, 0);
    EXPECT_GE(same.interior_psnr_db, 40.0);
    // The cut-outs show: the masked and the opaque lamp differ.
    EXPECT_NE(testing::render_once(gl::Backend::Egl, masked, lamp_frame()).rgb,
              testing::render_once(gl::Backend::Egl, opaque, lamp_frame()).rgb);
}

TEST(LampsRender, ExposureAgreesWithTheTracerOnTheLampHall) {
    const layout::Layout l = testing::layout_from_file(std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/lamp_hall.json");
    render::FrameDesc f;
    f.head = {{-1.7, 1.6, 0.4}, -80, -15, 0.0};
    f.room = layout::find_room(l, "hall");
    f.eye_width = 200;
    f.eye_height = 120;
    const image::Image plain = testing::render_once(gl::Backend::Egl, l, f);
    f.exposure = 0.0;
    EXPECT_EQ(testing::render_once(gl::Backend::Egl, l, f).rgb, plain.rgb);
    for (const double ev : {-2.0, 2.0}) {
        f.exposure = ev;
        const std::string what = "lamp hall at " + std::string(ev > 0 ? "+2" : "-2") + " EV";
        const image::Comparison cmp = against_tracer(l, f, what.c_str());
        EXPECT_EQ(cmp.id_mismatches, 0) << what;
        EXPECT_GE(cmp.interior_psnr_db, 40.0) << what;
        EXPECT_NE(testing::render_once(gl::Backend::Egl, l, f).rgb, plain.rgb) << what;
    }
    // A "fixed" layout is exposed alike.
    const layout::Layout fixed =
        testing::layout_from_file(std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/default.json");
    render::FrameDesc g;
    g.room = fixed.start.room;
    g.head.position = fixed.start.position;
    g.eye_width = 160;
    g.eye_height = 100;
    g.exposure = 1.0;
    const image::Comparison cmp = against_tracer(fixed, g, "default layout (fixed light) at +1 EV");
    EXPECT_EQ(cmp.id_mismatches, 0);
    EXPECT_GE(cmp.interior_psnr_db, 40.0);
}

}  // namespace
}  // namespace impossible
