// The cases issue 22 lists for crossing objects, each against the tracer at
// 0 id mismatches (one-pixel edge tolerance), in both clip modes, at depth 1,
// 8 and 64: eyes a millimetre from a crossing object's cut, one eye in a door
// box with a hand beside it, a crossing object seen through a second door,
// and a box sliding through a turned door every 0.1 s across its crossing.
#include <string>

#include "crossing_rig.hpp"

namespace impossible {
namespace {

// "a" and "b" fill one floor, joined by coincident doors across z = 0, with
// a crate standing half through them. "hall" has a door in its +x wall whose
// partner is in a's +z wall, turned by 90°: looking through it one sees the
// crate from a's +z side, and its far half through the second door. A box
// in the hall slides through that door and back. The free-standing door
// starts 0.1 m above the floor: a door box's bottom face in the floor's
// plane would make the two coplanar, which the spec leaves undefined, for
// an eye in the box's column looking down.
const char* kLayout = R"({
  "format": "impossible-layout", "version": 1,
  "start": { "room": "a", "position": [-0.9, 1.6, 1.7] },
  "rooms": [
    { "id": "a", "min": [-2, 0, -2], "max": [2, 3, 2], "color": [0.86, 0.82, 0.72],
      "props": [ { "id": "crate", "box": { "min": [-0.5, 0, -0.4], "max": [0.3, 0.8, 0.4] },
                   "color": [0.62, 0.40, 0.22] } ] },
    { "id": "b", "min": [-2, 0, -2], "max": [2, 2.6, 2], "color": [0.64, 0.78, 0.62], "checker": 0.5 },
    { "id": "hall", "min": [-2, 0, -2], "max": [2, 3, 2], "color": [0.84, 0.80, 0.72],
      "face_colors": { "floor": [0.3, 0.3, 0.4] },
      "props": [ { "id": "slider", "box": { "min": [0.4, 0, -0.3], "max": [1.0, 0.6, 0.3] }, "color": [0.9, 0.55, 0.15],
                   "motion": { "path": [[0, 0, 0, 0], [3, 2.6, 0, 0], [6, 0, 0, 0]], "loop": true } } ] }
  ],
  "portals": [
    { "id": "a_b", "room": "a", "center": [0, 1.2, 0], "normal": [0, 0, 1], "width": 1.6, "height": 2.2,
      "target": "b_a" },
    { "id": "b_a", "room": "b", "center": [0, 1.2, 0], "normal": [0, 0, -1], "width": 1.6, "height": 2.2,
      "target": "a_b" },
    { "id": "hall_east", "room": "hall", "center": [2, 1.1, 0], "normal": [-1, 0, 0], "width": 1.2,
      "height": 2.2, "target": "a_south" },
    { "id": "a_south", "room": "a", "center": [0, 1.1, 2], "normal": [0, 0, -1], "width": 1.2, "height": 2.2,
      "target": "hall_east" }
  ]
})";

using testing::CrossingRig;
using testing::expect_agree;
using testing::frame_at;

// The frame at each depth and in each clip mode, against the tracer.
void expect_agree_everywhere(CrossingRig& rig, render::FrameDesc f, const std::string& what) {
    for (const int depth : {1, 8, 64}) {
        f.max_depth = depth;
        const image::Image traced = rig.trace(f);
        for (const render::ClipMode clip : {render::ClipMode::ClipDistance, render::ClipMode::Oblique}) {
            f.clip = clip;
            expect_agree(rig.render(f), traced,
                         what + ", depth " + std::to_string(depth) +
                             (clip == render::ClipMode::Oblique ? ", oblique" : ", clip distance"));
        }
    }
}

TEST(CrossingCases, EyesAMillimetreFromTheCut) {
    CrossingRig rig(kLayout);
    ASSERT_TRUE(rig.renderer);
    // Above the crate, looking down at its top where the door's plane cuts
    // it: both eyes 1 mm in front of the plane, then 1 mm behind it (in the
    // door box's column, seeing b through its inner faces).
    for (const double z : {0.001, -0.001}) {
        render::FrameDesc f = frame_at(rig.layout, "a", {-0.1, 1.0, z}, 0.0, -70.0);
        expect_agree_everywhere(rig, f, "eyes at z = " + std::to_string(z));
    }
    // Looking along the cut, the eyes 1 mm off the plane at the crate's side.
    render::FrameDesc f = frame_at(rig.layout, "a", {1.0, 0.5, 0.001}, 90.0, -5.0);
    expect_agree_everywhere(rig, f, "along the cut");
}

TEST(CrossingCases, OneEyeInTheDoorBoxWithAHandBesideIt) {
    CrossingRig rig(kLayout);
    ASSERT_TRUE(rig.renderer);
    // Yaw 90 looks along -x: the eyes lie along z, the left one 1.2 cm
    // behind the door's plane (in its box), the right one in front; a hand
    // beside the head reaches through the door.
    render::FrameDesc f = frame_at(rig.layout, "a", {0.6, 1.4, 0.02}, 90.0, -10.0);
    f.hands = std::array<math::HeadPose, 2>{math::HeadPose{{0.35, 1.3, 0.03}, 90.0, 0.0, 0.0},
                                            math::HeadPose{{0.3, 1.25, -0.05}, 60.0, -20.0, 10.0}};
    expect_agree_everywhere(rig, f, "one eye in the box, hands beside");
}

TEST(CrossingCases, ACrossingObjectSeenThroughASecondDoor) {
    CrossingRig rig(kLayout);
    ASSERT_TRUE(rig.renderer);
    // From the hall through its east door into a (turned by 90°): the crate's
    // near half in a, and its far half through a's door into b.
    render::FrameDesc f = frame_at(rig.layout, "hall", {0.2, 1.5, 0.0}, -90.0, -12.0);
    expect_agree_everywhere(rig, f, "through the hall's door");
}

TEST(CrossingCases, TheSlidingBoxEveryTenthOfASecondAcrossItsCrossing) {
    CrossingRig rig(kLayout);
    ASSERT_TRUE(rig.renderer);
    // The slider meets the door from t = 1.15 s to 1.85 s (its front at
    // x = 2 to its back at x = 2).
    for (int k = 10; k <= 20; ++k) {
        render::FrameDesc f = frame_at(rig.layout, "hall", {-1.2, 1.6, 1.2}, -55.0, -12.0);
        f.time = 0.1 * k;
        expect_agree_everywhere(rig, f, "slider at t = " + std::to_string(f.time));
    }
}

}  // namespace
}  // namespace impossible
