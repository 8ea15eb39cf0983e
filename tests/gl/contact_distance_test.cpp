// Eyes touching surfaces (issue "exact at contact distance"): 0.1, 0.5 and
// 1 mm from a wall, from a prop, and from the back face of door boxes 2 cm
// and 4 cm deep (one eye inside the box, the head still in front of the
// door), in both clip modes. The rasteriser must show what the tracer shows:
// with a 1 cm near plane the wall vanished and the box's back showed the
// eye's own room.
#include <cmath>
#include <cstdio>

#include "cli/view_options.hpp"
#include "common/depth_precision.hpp"
#include "gl_fixture.hpp"
#include "image/compare.hpp"
#include "math/projection.hpp"
#include "trace/tracer.hpp"

namespace impossible {
namespace {

// The contact layout at the origin, and moved 2 km away (contact_far.json),
// where 32-bit float coordinates are 122 µm apart: there an eye 0.1 mm from a
// wall is exact only because each cell's vertices are relative to an origin
// of its own (scene::CellOrigin).
struct Placement {
    const char* file;
    math::dvec3 offset;
};
const Placement kPlacements[] = {{"contact.json", {0, 0, 0}}, {"contact_far.json", {1600.3, 0, -1300.7}}};

std::string layout_path(const Placement& at) { return std::string(IMPOSSIBLE_TEST_DATA) + "/layouts/hard/" + at.file; }

long mismatches(const layout::Layout& l, render::FrameDesc f, const std::string& what) {
    f.eye_width = 200;
    f.eye_height = 120;
    long worst = 0;
    for (render::ClipMode clip : {render::ClipMode::ClipDistance, render::ClipMode::Oblique}) {
        f.clip = clip;
        const image::Image raster = testing::render_once(gl::Backend::Egl, l, f);
        const image::Image traced = trace::trace_frame(l, cli::trace_desc_for(f)).value();
        const image::Comparison c = image::compare_pictures(raster, traced);
        std::printf("  %-52s %-13s %s\n", what.c_str(), clip == render::ClipMode::Oblique ? "oblique" : "clip-distance",
                    image::summary_line(c).c_str());
        worst = std::max(worst, c.id_mismatches);
    }
    return worst;
}

render::FrameDesc pose(const layout::Layout& l, math::dvec3 p, double yaw, double ipd = 0.064) {
    render::FrameDesc f;
    f.head.position = p;
    f.head.yaw_deg = yaw;
    f.room = layout::find_room(l, "a");
    f.ipd = ipd;
    return f;
}

const double kContacts[] = {1e-4, 5e-4, 1e-3};

TEST(ContactDistance, EyesAtAWallAndAProp) {
    for (const Placement& at : kPlacements) {
        const layout::Layout l = testing::layout_from_file(layout_path(at));
        for (double d : kContacts) {
            char what[96];
            std::snprintf(what, sizeof what, "%s: both eyes %g mm from the -z wall", at.file, d * 1e3);
            EXPECT_EQ(mismatches(l, pose(l, at.offset + math::dvec3{0, 1.6, -2 + d}, 0), what), 0) << what;
            std::snprintf(what, sizeof what, "%s: both eyes %g mm from the prop's +z face", at.file, d * 1e3);
            EXPECT_EQ(mismatches(l, pose(l, at.offset + math::dvec3{1.0, 0.6, -0.5 + d}, 0), what), 0) << what;
        }
    }
}

TEST(ContactDistance, OneEyeAtTheBackOfAShallowDoorBox) {
    // Yaw 45: the right eye sits ipd/2 · sin 45 behind the head along -n.
    const double s = std::sin(math::radians(45.0));
    const struct {
        const char* door;
        double depth, z, ipd;
    } boxes[] = {{"2 cm", 0.02, 0.5, 0.064}, {"4 cm", 0.04, 1.2, 0.12}};
    for (const Placement& at : kPlacements) {
        const layout::Layout l = testing::layout_from_file(layout_path(at));
        for (const auto& b : boxes) {
            for (double d : kContacts) {
                const double head_d = -b.depth + d + s * b.ipd / 2;  // right eye at -depth + d
                ASSERT_GT(head_d, 0.0);
                const double x = b.z == 0.5 ? -1.0 : 1.0;
                const math::dvec3 head = at.offset + math::dvec3{x - s * b.ipd / 2 + 0.1, 1.5, b.z + head_d};
                char what[112];
                std::snprintf(what, sizeof what, "%s: right eye %g mm from the back of a %s deep box", at.file, d * 1e3,
                              b.door);
                EXPECT_EQ(mismatches(l, pose(l, head, 45, b.ipd), what), 0) << what;
            }
        }
    }
}

// What the 10 µm near plane costs in depth precision (docs/accuracy.md):
// under reversed-Z float depth nothing measurable; 24-bit standard depth
// would lose a factor 1000, so it keeps its 1 cm near plane.
TEST(ContactDistance, TheSmallNearPlaneCostsNoDepthPrecisionUnderReversedZ) {
    math::Frustum wide;
    wide.fov_y_deg = 90.0;
    wide.aspect = 16.0 / 9.0;
    for (double z : {10.0, 1000.0, 10000.0}) {
        wide.near = render::kNearReversedZ;
        const double rev_small = testing::resolvable_separation(math::perspective_reversed_z(wide), z, true, true);
        wide.near = 0.01;
        const double rev_cm = testing::resolvable_separation(math::perspective_reversed_z(wide), z, true, true);
        const double std_cm = testing::resolvable_separation(math::perspective_standard(wide, 2e5), z, false, false);
        wide.near = render::kNearReversedZ;
        const double std_small = testing::resolvable_separation(math::perspective_standard(wide, 2e5), z, false, false);
        std::printf(
            "  at %5g m: reversed-Z near 10 um %.3g m, near 1 cm %.3g m; standard near 1 cm %.3g m, near 10 um %.3g "
            "m\n",
            z, rev_small, rev_cm, std_cm, std_small);
        EXPECT_LT(rev_small, rev_cm * 1.01);
        EXPECT_LT(rev_small, z * 2e-7);  // about z · 2^-24 · 2
        EXPECT_GT(std_small, std_cm * 100.0);
    }
}

}  // namespace
}  // namespace impossible
