// What the page asks of one frame (web/page.js, web/xr.js), read from JSON,
// and the drawn frame shown in the canvas or a headset's framebuffer.
//
//   {"head": {"position": [x, y, z], "orientation": [x, y, z, w]},
//    "space": "layout" | "floor",   // floor: the layout's start at the origin
//    "eyes": [{"position": [...], "orientation": [...], "fov": [l, r, u, d]}, {...}],
//    "ipd": 0.064, "fov_y": 90,      // without "eyes"
//    "size": [w, h], "hands": [{pose}, {pose}], "time": t,
//    "depth": "reversed-z" | "standard", "max_depth": n, "clip": "oblique", "cull": false,
//    "finish": true,                 // wait for the GPU before returning
//    "target": {"framebuffer": id, "viewports": [[x, y, w, h], [x, y, w, h]]}}
//
// Poses are WebXR's: positions in metres, orientations unit quaternions;
// eyes relative to the head; fov in degrees (OpenXR's angles, from the
// view's projection matrix).
#pragma once

#include <array>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "layout/layout.hpp"
#include "render/frame.hpp"
#include "render/target.hpp"
#include "walk/replay.hpp"

namespace impossible::web {

struct FrameRequest {
    math::HeadPose physical_head;
    walk::HandPoses hands;
    double time = 0.0;
    render::FrameDesc frame;  // the eyes, size and technique; head and room come from the walk
    unsigned framebuffer = 0;
    std::array<std::array<int, 4>, 2> viewports{};  // per eye; w = 0: the frame's own size side by side
    bool finish = false;                            // wait for the GPU (the web bench's frame times)
};

// Throws std::runtime_error naming the field for a malformed request.
FrameRequest parse_frame_request(const nlohmann::json& request, const layout::Layout& layout);

// --pose (the physical head), --eye-poses (each eye's position and yaw,
// pitch, roll in the head's coordinates) or --ipd and --fov, --fov-angles
// (eight numbers) and --size: the options with which `render` and `trace`
// draw the request's two eye views; numbers in the shortest form that
// reads back the same.
std::string frame_view_options(const FrameRequest& request);

// Blits each eye's half of the target into its viewport of the request's
// framebuffer (0: the canvas).
void present(const render::Target& target, const FrameRequest& request);

}  // namespace impossible::web
