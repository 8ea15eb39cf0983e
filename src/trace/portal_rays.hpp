// A brute force of the seen test (changes/seen.hpp; layout-format.md,
// "Changes while walking") on the tracer's side: the pixel-centre rays of
// both eyes of a view, followed through the scene's portals as the tracer
// follows view rays, with room faces and props ignored. Which portals some
// ray reaches is a lower bound of what the seen test must call seen: every
// portal reached here is one the seen test may not call unseen.
//
// Each ray (every `step`-th pixel of each eye image, row and column, from
// pixel (0, 0); hidden pixels of a headset's visible area left out, as
// trace_frame leaves them) meets, in its cell, the nearest of the cell's
// portals that it hits: a portal's front rectangle from its front side (in
// the portal's own plane, also for a portal that fills a hole, whose face
// the tracer would meet at the face's plane within kHolePlaneTolerance),
// and a door's inner faces where the (possibly virtual) eye has them
// (hit_portal_box, math::has_inner_faces), each strictly in front of the
// clip plane (ClipPlane::keeps). That portal is reached. While fewer than
// max_depth portals were passed on the line of sight and the ray tree has
// made fewer than max_portal_passes passes, the ray goes on as the tracer's
// does: through a door to its target (its plane clipping when the virtual
// eye is behind it), reflected by a mirror, and both ways at a window, each
// branch whatever its weight (the seen test reads no tint either).
#pragma once

#include <vector>

#include "math/view.hpp"
#include "trace/trace_scene.hpp"

namespace impossible::trace {

struct PortalRays {
    std::vector<char> reached;  // per portal of the scene: 1 where some ray reached it
    long rays = 0;              // pixel rays followed (both eyes)
    long passes = 0;            // portal passes made (all rays)
};

// The portals that the pixel rays of `view` (its room, head, eyes, frusta,
// visible areas, max_depth and max_portal_passes) reach in `scene`; every
// `step`-th pixel (step ≥ 1). The view's room must be one of the scene's
// and its image size positive.
PortalRays portal_rays(const Scene& scene, const math::View& view, int step = 1);

}  // namespace impossible::trace
