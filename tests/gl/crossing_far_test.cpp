// A hand reaching through a door far from the layout's origin, against the
// tracer (diff_fuzz seed 22 case 7528): the image's strict cut was moved
// towards its kept side by 1 µm times the door plane's distance from the
// layout's origin, 1.25 mm at 1.25 km, which opened a gap between the hand's
// own part and its image, showing the room behind the door through it.
#include <string>

#include "crossing_rig.hpp"

namespace impossible {
namespace {

// Two rooms 2.3 km from the origin, joined by coincident 7 cm wide doors across
// x = -1254.095306 (diff_fuzz seed 22 case 7528 without its props).
const char* kFarLayout = R"({
  "format": "impossible-layout", "version": 1,
  "start": { "room": "a", "position": [-1254.036466, 1.261726, -1915.625575] },
  "rooms": [
    { "id": "a", "min": [-1257.531035, 0, -1919.139415], "max": [-1252.353019, 2.521063, -1912.131095],
      "color": [0.815, 0.525, 0.712] },
    { "id": "b", "min": [-1257.172284, 0, -1919.327497], "max": [-1253.073957, 2.712771, -1912.87922],
      "color": [0.659, 0.721, 0.248] }
  ],
  "portals": [
    { "id": "a_door", "room": "a", "center": [-1254.095306, 1.326733, -1915.613952], "normal": [1, 0, 0],
      "width": 0.069971, "height": 1.191175, "target": "b_door", "depth": 0.072714 },
    { "id": "b_door", "room": "b", "center": [-1254.095306, 1.326733, -1915.613952], "normal": [-1, 0, 0],
      "width": 0.069971, "height": 1.191175, "target": "a_door", "depth": 0.080985 }
  ]
})";

TEST(CrossingFar, AHandThroughADoorTwoKilometresOutShowsNoGapAtTheCut) {
    testing::CrossingRig rig(kFarLayout);
    ASSERT_TRUE(rig.renderer);
    // The eyes 5.9 cm in front of the door, both hands pushed through it:
    // the first into b (its image in a), the second meeting a's door.
    render::FrameDesc f =
        testing::frame_at(rig.layout, "a", {-1254.0364661901931, 1.2617263172788031, -1915.6255750222115},
                          87.948609521150644, -8.1229944897517257);
    f.eye_width = 192;
    f.eye_height = 128;
    f.fov_y_deg = 103.211;
    f.hands =
        std::array<math::HeadPose, 2>{math::HeadPose{{-1254.1815108092128, 1.4119593783424689, -1915.6199088792673},
                                                     115.52106739565653,
                                                     -32.300542551685282,
                                                     -51.793388242194894},
                                      math::HeadPose{{-1254.10588397738, 1.3169087772943087, -1915.6204592693655},
                                                     155.72112729337988,
                                                     19.63277452542772,
                                                     -83.41898553497694}};
    const image::Image traced = rig.trace(f);
    for (const render::ClipMode clip : {render::ClipMode::ClipDistance, render::ClipMode::Oblique}) {
        f.clip = clip;
        testing::expect_agree(
            rig.render(f), traced,
            clip == render::ClipMode::Oblique ? "hands 2.3 km out, oblique" : "hands 2.3 km out, clip distance");
    }
}

}  // namespace
}  // namespace impossible
