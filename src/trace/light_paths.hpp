// The light that reaches a surface point under "lighting": "lights"
// (layout-format.md, "Lights"), found exactly: every light path of at most
// `light_depth` portals, each checked by a shadow ray through the tracer's
// own intersections (nearest.hpp, nearest_for_light). Internal to src/trace
// (tracer.cpp); see docs/tracer.md, "Lights". The formulas are
// shading/lighting.hpp's, shared with the rasteriser; the enumeration is the
// tracer's own (src/lights is the rasteriser's, which this one checks).
#pragma once

#include "trace/trace_scene.hpp"

namespace impossible::trace {

// A surface point to light: `point` in the coordinates of `room` (the room
// the surface belongs to, whose lights and portals it sees), `normal` unit
// and facing the viewer's side.
struct LitPoint {
    int room = -1;
    dvec3 point{0.0};
    dvec3 normal{0.0};
};

// Σ contribution over every light path to the point (before the ambient and
// the clamp): paths are sequences of at most `light_depth` (0..16) portals
// (door, mirror, a window passed through or reflecting), followed depth
// first from the point's room; a path whose factor's largest channel falls
// below shading::kMinLightFactor is not followed. `objects` are the frame's
// (null: none), which shadow rays meet as view rays do.
dvec3 light_sum(const Scene& scene, const FrameObjects* objects, const LitPoint& at, int light_depth);

}  // namespace impossible::trace
