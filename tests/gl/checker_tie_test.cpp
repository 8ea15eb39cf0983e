// The checker pattern on a wall at 45° (shading::checker_dark): its normal's
// x and z are equal up to rounding, and the rasteriser (a float normal
// interpolated per pixel) and the tracer (the exact normal in double) must
// pick the same two coordinates for its squares. Before the tie rule they
// broke the tie differently, pixel by pixel (seed 43 case 297 of the lit
// prism fuzz: 37 dB).
#include <cstdio>
#include <string>

#include "cli/view_options.hpp"
#include "gl_fixture.hpp"
#include "image/compare.hpp"
#include "shading/shading.hpp"
#include "trace/tracer.hpp"

namespace impossible {
namespace {

TEST(CheckerTie, NearlyEqualComponentsTieToYThenZ) {
    const double s = 0.5;
    // |x| and |z| within the tie: z's plane (x and y) in both orders.
    const glm::dvec3 q(0.3, 0.2, 0.7);  // squares by x, y: 0, 0, light; by y, z: 0, 1, dark
    EXPECT_FALSE(shading::checker_dark(q, glm::normalize(glm::dvec3(1.0, 0.0, 1.0 - 5e-5)), s));
    EXPECT_FALSE(shading::checker_dark(q, glm::normalize(glm::dvec3(1.0 - 5e-5, 0.0, 1.0)), s));
    // Beyond the tie the larger wins.
    EXPECT_TRUE(shading::checker_dark(q, glm::normalize(glm::dvec3(1.0, 0.0, 0.99)), s));
    // y wins its ties too (x and z).
    const glm::dvec3 r(0.7, 0.7, 0.2);  // by x, z: 1, 0, dark; by x, y: 1, 1, light
    EXPECT_TRUE(shading::checker_dark(r, glm::normalize(glm::dvec3(0.0, 1.0, 1.0 - 5e-5)), s));
    EXPECT_FALSE(shading::checker_dark(r, glm::normalize(glm::dvec3(0.0, 0.99, 1.0)), s));
}

std::string turned_square(bool lit) {
    std::string room =
        "{\"id\": \"diamond\", \"floor\": [[-6.296812, 27.785056], [-3.779405, 30.302463], [-0.832014, 27.355073], "
        "[-3.349422, 24.837666]], \"y\": [0, 2.7], \"color\": [0.8, 0.7, 0.5], \"checker\": 0.25";
    if (lit)
        room += ", \"ambient\": [0.2, 0.2, 0.2], \"lights\": [{\"position\": [-3.3, 2.2, 27.2], \"intensity\": 4}]";
    return std::string("{\"format\": \"impossible-layout\", \"version\": 1, ") +
           (lit ? "\"lighting\": \"lights\", " : "") +
           "\"start\": {\"room\": \"diamond\", \"position\": [-3.5, 1.6, 27.6]}, \"rooms\": [" + room + "}]}";
}

TEST(CheckerTie, AWallAt45DegreesHasOnePattern) {
    for (const bool lit : {false, true}) {
        const layout::Layout l = testing::layout_from_text(turned_square(lit));
        // A rectangle turned 45° in decimal (fuzz seed 43 case 297's room b),
        // not in binary: facing its corners and its walls.
        for (const double yaw : {0.0, 45.0, 90.0, 135.0, 200.0}) {
            render::FrameDesc f;
            f.head = {{-3.4, 1.5, 27.5}, yaw, -10.0, 0.0};
            f.room = 0;
            f.eye_width = 160;
            f.eye_height = 96;
            const image::Image raster = testing::render_once(gl::Backend::Egl, l, f);
            const image::Image traced = trace::trace_frame(l, cli::trace_desc_for(f)).value();
            const image::Comparison c = image::compare_pictures(raster, traced);
            std::printf("  %s yaw %5.1f: %s\n", lit ? "lit  " : "fixed", yaw, image::summary_line(c).c_str());
            EXPECT_EQ(c.id_mismatches, 0);
            EXPECT_GE(c.interior_psnr_db, 50.0) << (lit ? "lit" : "fixed") << " yaw " << yaw;
        }
    }
}

}  // namespace
}  // namespace impossible
