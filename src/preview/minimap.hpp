// The preview's minimap: the play area in physical coordinates (x right, -z
// up, so the start's yaw 0 looks up), the current room's floor (its
// rectangle, or a prism room's polygon) mapped into it
// by the inverse of the walker's W, the rooms one door away mapped through
// their doors (so rooms sharing the same floor show as overlapping
// outlines), the current room's portals (doors orange, mirrors silver,
// windows blue, minimap_portal_colour), and the head with its view direction.
#pragma once

#include <optional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "layout/layout.hpp"
#include "math/pose.hpp"
#include "preview/overlay.hpp"

namespace impossible::preview {

struct MinimapInput {
    const layout::Layout* layout = nullptr;
    int room = 0;
    math::dmat4 physical_to_virtual{1.0};
    const std::vector<math::dmat4>* transfer = nullptr;  // M per portal, to its target
    math::HeadPose physical_head;
};

// The physical (x, z) rectangle the minimap shows: the play area, the current
// room's footprint and the head, with a margin.
struct MapBounds {
    glm::dvec2 min{0.0}, max{0.0};
};
MapBounds minimap_bounds(const MinimapInput& in);

// The outline colour of a portal of the current room.
glm::vec4 minimap_portal_colour(layout::PortalKind kind);

// Draws the minimap into the square panel at pixel `corner` (top left) of
// side `size`.
void add_minimap(OverlayBatch& batch, const MinimapInput& in, glm::vec2 corner, float size);

}  // namespace impossible::preview
