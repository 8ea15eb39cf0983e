// Each eye's pose through the public API (docs/api.md, "Headsets"):
// View::eye_poses reaches the library's view as `--eye-poses` does, a
// profile's poses are read, bad ones are refused naming the field, and
// frames equal the command's byte for byte.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "api/api_data.hpp"
#include "common/png.hpp"
#include "common/temp_dir.hpp"
#include "impossible/impossible.hpp"
#include "math/eyes.hpp"

namespace impossible::api::eye_poses_test {
namespace {

std::string source_file(const std::string& name) { return std::string(IMPOSSIBLE_SOURCE_DIR) + "/" + name; }

// Each eye turned 5° outwards (as `--eye-poses -0.032,0,0,5,0,0,0.032,0,0,-5,0,0`).
std::array<EyePose, 2> canted() {
    return {eye_pose(Pose{-0.032, 0, 0, 5, 0, 0}), eye_pose(Pose{0.032, 0, 0, -5, 0, 0})};
}

std::string problem(const View& view) {
    const Result<math::View> v = resolve_view(Layout::builtin().data().layout, view);
    return v ? "(none)" : v.error();
}

TEST(ApiEyePoses, ReachTheViewAsTheCommandsAngles) {
    View view;
    view.eye_poses = canted();
    const Result<math::View> v = resolve_view(Layout::builtin().data().layout, view);
    ASSERT_TRUE(v) << v.error();
    ASSERT_TRUE(v->eye_offsets);
    // --eye-poses turns its angles into rotations the same way (math::eye_offset).
    EXPECT_EQ((*v->eye_offsets)[0], math::eye_offset(math::HeadPose{{-0.032, 0, 0}, 5, 0, 0}));
    EXPECT_EQ((*v->eye_offsets)[1], math::eye_offset(math::HeadPose{{0.032, 0, 0}, -5, 0, 0}));
    EXPECT_EQ(canted()[0].orientation[1], std::sin(math::radians(2.5)));
    view.eye_poses.reset();
    EXPECT_FALSE(resolve_view(Layout::builtin().data().layout, view)->eye_offsets);
}

TEST(ApiEyePoses, BadPosesAreRefusedNamingTheField) {
    View view;
    view.eye_poses = canted();
    (*view.eye_poses)[1].orientation = {0, 0, 0, 1.000002};
    EXPECT_EQ(problem(view),
              "eye_poses: right eye: the orientation is not a unit quaternion (x, y, z, w): its length is 1.000002, "
              "not 1 within 1e-6");
    (*view.eye_poses)[1].orientation = {0, 0, 0, 1.0000005};  // within 1e-6: normalised
    EXPECT_EQ(problem(view), "(none)");
    (*view.eye_poses)[0].position = {0, 1.2, 0};
    EXPECT_EQ(problem(view), "eye_poses: left eye: the position is 1.2 m from the head centre, more than 1 m");
    (*view.eye_poses)[0].position = {0, NAN, 0};
    EXPECT_EQ(problem(view), "eye_poses: left eye: the position holds a number that is not finite");
}

TEST(ApiEyePoses, ProfilePosesAreRead) {
    const Expected<HmdProfile> profile = load_hmd_profile(source_file("profiles/canted-5deg.json"));
    ASSERT_TRUE(profile) << profile.error().message;
    ASSERT_TRUE(profile->eye_poses);
    EXPECT_EQ((*profile->eye_poses)[0].position, (std::array<double, 3>{-0.03175, 0, 0}));
    EXPECT_EQ((*profile->eye_poses)[1].orientation[1], -0.043619387365336);
    View view;
    use_hmd_profile(view, *profile);
    EXPECT_TRUE(view.eye_poses);
    const Expected<HmdProfile> vive = load_hmd_profile(source_file("profiles/htc-vive.json"));
    ASSERT_TRUE(vive) << vive.error().message;
    EXPECT_FALSE(vive->eye_poses);
    use_hmd_profile(view, *vive);
    EXPECT_FALSE(view.eye_poses);  // the Vive's eyes follow its IPD
}

// `render`/`trace --eye-poses ...` and `--hmd canted-5deg.json`, byte for
// byte (colour and ids).
TEST(ApiEyePoses, RenderAndTraceEqualTheCommands) {
    const std::string layout_path = source_file("layouts/four_rooms.json");
    const std::string hmd = source_file("profiles/canted-5deg.json");
    const Expected<Layout> l = Layout::load(layout_path);
    ASSERT_TRUE(l) << l.error().message;
    Expected<Renderer> renderer = Renderer::headless(*l);
    ASSERT_TRUE(renderer) << renderer.error().message;
    View by_angles;
    by_angles.width = 72;
    by_angles.height = 60;
    by_angles.eye_poses = canted();
    View by_profile;
    use_hmd_profile(by_profile, *load_hmd_profile(hmd));
    by_profile.width = 72;
    by_profile.height = 60;
    const test::TempDir dir("api_eye_poses");
    struct Case {
        const View& view;
        std::string options;
    };
    for (const Case& c :
         {Case{by_angles, "--eye-poses -0.032,0,0,5,0,0,0.032,0,0,-5,0,0"}, Case{by_profile, "--hmd '" + hmd + "'"}}) {
        for (const std::string command : {"render", "trace"}) {
            const std::string colour = (dir / "c.png").string(), ids = (dir / "i.png").string();
            const std::string line = std::string(IMPOSSIBLE_BINARY) + " " + command + " '" + layout_path + "' " +
                                     c.options + " --size 72x60 --out '" + colour + "' --ids '" + ids + "'";
            ASSERT_EQ(std::system(line.c_str()), 0) << line;
            const Expected<Frame> frame = command == "render" ? renderer->render(c.view) : trace(*l, c.view);
            ASSERT_TRUE(frame) << frame.error().message;
            EXPECT_TRUE(frame->rgb == testing::read_png_ok(colour).data) << line;
            EXPECT_TRUE(frame->ids == testing::read_png_ok(ids).data) << line;
        }
    }
}

// docs/api.md's example (Headsets, eye poses), as it is there.
TEST(ApiEyePoses, TheDocsExample) {
    namespace api = impossible::api;
    api::View canted;  // each eye turned 5° outwards, as canted displays are
    canted.eye_poses =
        std::array<api::EyePose, 2>{api::eye_pose({-0.032, 0, 0, 5, 0, 0}), api::eye_pose({0.032, 0, 0, -5, 0, 0})};

    api::View index_like;
    api::use_hmd_profile(index_like, *api::load_hmd_profile(source_file("profiles/canted-5deg.json")));

    const Result<math::View> a = resolve_view(Layout::builtin().data().layout, canted);
    const Result<math::View> b = resolve_view(Layout::builtin().data().layout, index_like);
    ASSERT_TRUE(a && b);
    EXPECT_EQ((*a->eye_offsets)[0].rotation, (*b->eye_offsets)[0].rotation);  // the same 5° turn
    EXPECT_EQ((*b->eye_offsets)[1].position, math::dvec3(0.03175, 0, 0));
}

}  // namespace
}  // namespace impossible::api::eye_poses_test
