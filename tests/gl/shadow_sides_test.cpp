// One-sided faces and shadows (layout-format.md, "Lights": a shadow ray
// meets only the front faces of surfaces, as a view ray does): a one-sided
// glTF quad with a lamp in front of it casts no shadow behind it, in the
// shadow maps as in the tracer; made double-sided, it does, in both.
#include <cstdio>

#include "cli/view_options.hpp"
#include "gl_fixture.hpp"
#include "image/compare.hpp"
#include "trace/tracer.hpp"

namespace impossible {
namespace {

const char* kLitRoom = R"({
  "format": "impossible-layout", "version": 1, "lighting": "lights",
  "start": { "room": "room", "position": [0, 1.6, -2.5] },
  "rooms": [ { "id": "room", "min": [-3, 0, -3], "max": [3, 3, 3], "color": [0.8, 0.8, 0.8],
               "ambient": [0.05, 0.05, 0.05],
               "lights": [ { "position": [0, 1.0, 0.4], "intensity": 4 } ] } ]
})";

// A 1 m × 1 m quad in the plane z = 0, 0.5 m to 1.5 m high, facing +z (the lamp).
layout::GltfProp quad(bool double_sided) {
    layout::GltfProp prop;
    prop.path = prop.resolved_path = "<quad>";
    const glm::dvec3 bl(-0.5, 0.5, 0), br(0.5, 0.5, 0), tr(0.5, 1.5, 0), tl(-0.5, 1.5, 0);
    for (const std::array<glm::dvec3, 3>& corners : {std::array{bl, br, tr}, std::array{bl, tr, tl}}) {
        assets::ModelTriangle t;
        t.position = corners;
        t.normal = {glm::dvec3(0, 0, 1), glm::dvec3(0, 0, 1), glm::dvec3(0, 0, 1)};
        t.uv = {glm::dvec2(0), glm::dvec2(0), glm::dvec2(0)};
        t.material = 0;
        t.color = glm::dvec3(0.6);
        prop.triangles.push_back(t);
    }
    assets::Material m;
    m.base_color = glm::dvec4(0.6, 0.6, 0.6, 1.0);
    m.double_sided = double_sided;
    prop.materials.push_back(m);
    return prop;
}

image::Comparison render_against_trace(bool double_sided) {
    layout::Layout l = testing::layout_from_text(kLitRoom);
    l.rooms[0].props.push_back(quad(double_sided));
    render::FrameDesc f;
    f.head = {{0.0, 1.8, -2.0}, 180.0, -35.0, 0.0};  // behind the quad, looking at the floor behind it
    f.room = 0;
    f.eye_width = 160;
    f.eye_height = 120;
    const image::Image raster = testing::render_once(gl::Backend::Egl, l, f);
    const image::Image traced = trace::trace_frame(l, cli::trace_desc_for(f)).value();
    return image::compare_pictures(raster, traced);
}

TEST(ShadowSides, AOneSidedQuadLetsTheLampLightTheFloorBehindIt) {
    const image::Comparison cmp = render_against_trace(false);
    std::printf("  one-sided: %s\n", image::summary_line(cmp).c_str());
    EXPECT_EQ(cmp.id_mismatches, 0);
    EXPECT_GE(cmp.interior_psnr_db, 50.0);  // before: 16 dB, the map shadowed what the tracer lights
}

TEST(ShadowSides, ADoubleSidedQuadShadowsTheFloorBehindIt) {
    const image::Comparison cmp = render_against_trace(true);
    std::printf("  double-sided: %s\n", image::summary_line(cmp).c_str());
    EXPECT_EQ(cmp.id_mismatches, 0);
    EXPECT_GE(cmp.interior_psnr_db, 40.0);  // a prop's shadow: the maps' approximation (docs/lighting.md)
}

}  // namespace
}  // namespace impossible
