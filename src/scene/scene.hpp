// GPU-ready geometry for a layout: one shared vertex/index array, with each
// room (cell) and each portal box an index range into it.
//
// Positions are in the layout's own coordinates (a room seen through a portal
// is drawn with its own geometry from a virtual camera, never moved). All
// triangles are counter-clockwise when seen from their front side; room faces
// face inwards, prop boxes outwards, portal boxes as the spec's "portal box".
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "layout/layout.hpp"
#include "scene/portal_links.hpp"

namespace impossible::scene {

struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;   // unit, on the visible side
    glm::vec3 color;    // base colour before shading
    float checker;      // checker square side in metres; 0: plain
};

struct IndexRange {
    std::uint32_t first = 0;  // first index in Scene::indices
    std::uint32_t count = 0;  // number of indices (a multiple of 3)
};

struct PortalMesh {
    IndexRange front;  // the rectangle in the plane, facing +normal
    IndexRange inner;  // four side faces and the back face, facing inwards
};

struct Scene {
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    std::vector<IndexRange> cells;     // per room: faces (with holes) and props
    std::vector<PortalMesh> portals;   // per portal, in the portal's room coordinates
    PortalLinks links;                 // M_AB per portal and the portals of each room, linked once
};

// Builds the meshes of every room and portal box, and links the portals. The
// layout must be valid (from the loader); glTF props use the triangles the
// loader read.
Scene build_scene(const layout::Layout& layout);

}  // namespace impossible::scene
