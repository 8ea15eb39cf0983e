// What one stereo frame looks at, whoever draws it: the head, the room it is
// in, the eyes and the image size. Declared once; the rasteriser's
// render::FrameDesc and the tracer's trace::TraceDesc extend it with their own
// settings (a FrameDesc hands the tracer its View as it is).
#pragma once

#include "math/pose.hpp"

namespace impossible::math {

struct View {
    math::HeadPose head;
    int room = 0;             // index of the room the head is in
    double ipd = 0.064;       // metres between the eyes
    double fov_y_deg = 90.0;  // vertical field of view of each eye
    int eye_width = 1280;     // each eye's image; the side-by-side image is 2 × width
    int eye_height = 720;
    int max_depth = 8;  // portals one line of sight may pass
};

}  // namespace impossible::math
