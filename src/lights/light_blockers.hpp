// Internal to src/lights: the blockers of a light image's legs
// (light_images.hpp, Blocker), for light_images.cpp. Only the blockers
// that some shadow ray of the image can meet are kept: a rectangle stops a
// segment towards the image only when crossed from its front, so one whose
// plane the image lies in front of never does, nor one wholly beyond the
// light's range (the light adds nothing there). That keeps the rectangles
// a fragment tests, which bounded-work.md ("Path rectangles") bounds, to
// those that may change its colour; the image is what it was.
#pragma once

#include <vector>

#include "lights/light_images.hpp"

namespace impossible::lights {

struct BlockerSource {
    const layout::Layout& layout;
    const links::PortalLinks& links;
    const std::vector<std::vector<int>>& crossable;  // per room: layout::crossable_walls
    bool cull = true;                                // false: keep those that cannot block too (tests)
};

// Appends every leg's blockers to `image`, whose rooms, to_room, apertures,
// position and light are set: the free-standing portals of each leg's room
// (but those the leg enters and leaves by), its crossable walls (but those
// two portals' walls) and the planes of faces it would leave the room by
// where a door of the leg reaches outside, less those that cannot block.
void add_blockers(const BlockerSource& source, LightImage& image);

}  // namespace impossible::lights
