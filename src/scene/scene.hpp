// GPU-ready geometry for a layout: one shared vertex/index array, with each
// room (cell) and each portal box an index range into it.
//
// Positions are in the layout's own coordinates (a room seen through a portal
// is drawn with its own geometry from a virtual camera, never moved), but
// measured from an origin of the room's own (CellOrigin): 32-bit floats a
// kilometre from the layout's origin are 61 µm apart, too coarse for an eye
// 0.1 mm from a wall; relative to the room they are as fine as the room's size
// allows. The renderer folds the origin into its double-precision matrices. All
// triangles are counter-clockwise when seen from their front side; room faces
// face inwards, prop boxes outwards, portal boxes as the spec's "portal box".
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "layout/layout.hpp"
#include "lights/light_images.hpp"
#include "links/portal_links.hpp"
#include "walk/objects.hpp"

namespace impossible::scene {

struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;    // unit, on the visible side
    glm::vec3 color;     // base colour before shading (and before the texel)
    float checker;       // checker square side in metres; 0: plain
    glm::vec2 uv{0.0f};  // texture coordinates, (0, 0) the image's top-left; unused untextured
    float alpha = 1.0f;  // alpha before the texel's, for alpha-masked batches
};

struct IndexRange {
    std::uint32_t first = 0;  // first index in Scene::indices
    std::uint32_t count = 0;  // number of indices (a multiple of 3)
};

// An image and how it is sampled, as the GPU needs it (its mipmaps are made
// on upload); room faces use the default sampler.
struct SceneTexture {
    std::shared_ptr<const image::Pixels> image;
    assets::Sampler sampler;
};

// Part of a cell drawn with one material state: a texture (or none) and an
// alpha cutoff (or none). A cell's batches cover its range in order; a cell
// without textures and cut-outs is one batch.
struct DrawBatch {
    IndexRange range;
    int texture = -1;            // into Scene::textures; -1: untextured (a white texel)
    float alpha_cutoff = -1.0f;  // fragments whose alpha is below it are dropped; < 0: opaque

    bool same_state(const DrawBatch& o) const { return texture == o.texture && alpha_cutoff == o.alpha_cutoff; }
};

// Where a room's vertices, and its portals' boxes', are measured from.
struct CellOrigin {
    glm::dvec3 origin{0.0};         // vertex position = layout coordinates - origin
    glm::vec3 checker_offset{0.0};  // origin modulo twice the room's checker side
};

// The room's centre rounded to the nearest multiple of kCellOriginGrid on each
// axis: a room within 32 m of the layout's origin keeps it (its vertices are
// the layout's coordinates, bit for bit), and no vertex lies farther than
// 32 m plus half the room's size from its cell's origin (float spacing 3.8 µm
// at 32 m), wherever the room is.
inline constexpr double kCellOriginGrid = 64.0;
CellOrigin origin_of_cell(const layout::Room& room);

struct PortalMesh {
    IndexRange front;  // the rectangle in the plane, facing +normal
    IndexRange inner;  // four side faces and the back face, facing inwards
};

// A portal as the rasteriser draws it, copied from the layout as plain data:
// where it stands, where it leads, and what it does to what is seen in it.
struct PortalInfo {
    math::PortalRect rect;  // in layout coordinates
    int room = -1;          // the room it stands in
    int target = -1;        // the portal it leads to; -1 for a mirror
    layout::PortalKind kind = layout::PortalKind::Door;
    glm::dvec3 tint{1.0};      // mirrors and windows: multiplies what is seen in them
    double reflectance = 0.0;  // windows: the reflected view's share
};

// A prop as per-object culling sees it: its bounds in layout coordinates
// (padded, scene/cell_objects.cpp) and its batches.
struct CellObject {
    glm::dvec3 lo{0.0};
    glm::dvec3 hi{0.0};
    std::uint32_t first_batch = 0;  // into CellObjects::batches
    std::uint32_t batch_count = 0;
    // A box prop: its first vertex (append_box_prop's 24, four per face,
    // faces -x, +x, -y, +y, -z, +z); -1 for a model. A level may then draw
    // only the faces its eyes can see (render/objects/box_faces.hpp).
    std::int64_t box_vertex = -1;
    glm::dvec3 box_min{0.0}, box_max{0.0};  // a box prop's corners as the layout writes them
};

// A node of a cell's bounding-volume hierarchy over its objects, stored depth
// first: an inner node's first child follows it.
struct CullNode {
    glm::dvec3 lo{0.0};
    glm::dvec3 hi{0.0};
    int first = 0;  // leaf: its first entry in CellObjects::order; inner: the second child's index
    int count = 0;  // leaf: its number of objects (> 0); inner: 0
};

// What a cell draws, split for culling: the room's faces always, each prop
// when its bounds may be seen.
struct CellObjects {
    // The room's largest box props (scene/cell_objects.hpp, occluders_of),
    // shrunk a little: whatever lies wholly in a box's shadow is hidden.
    std::vector<std::pair<glm::dvec3, glm::dvec3>> occluders;
    std::vector<DrawBatch> surfaces;  // the room's faces
    std::vector<CellObject> objects;  // the props, in the order they were written
    std::vector<DrawBatch> batches;   // the objects' batches, object after object
    std::vector<CullNode> nodes;      // nodes[0] is the root; empty without objects
    std::vector<int> order;           // object indices, leaf after leaf
};

// A dynamic object's mesh (walk/objects.hpp): a prop that moves or meets a
// door at rest, or the hand, drawn each frame as instances placed by
// walk::place_objects, never as part of a cell. Its vertices are in the
// object's own coordinates (a prop's: the layout's as written; the hand's:
// its frame) less `origin`.
struct ObjectMesh {
    std::vector<DrawBatch> batches;
    bool box = false;    // a box prop's (or box hand's): closed, wound outwards
    glm::dvec3 lo{0.0};  // bounds in its own coordinates, padded as CellObject's
    glm::dvec3 hi{0.0};
    glm::dvec3 origin{0.0};  // vertex position = own coordinates - origin
    // Its vertices: [first_vertex, vertex_end) of Scene::vertices.
    std::uint32_t first_vertex = 0, vertex_end = 0;
};

// Consecutive triangles of a volume's target room that may lie inside the
// volume (scene/volume_pieces.hpp), and where.
struct VolumePiece {
    DrawBatch batch;  // a run of one of the target's batches, with its state
    // Bounds of those triangles' parts inside the (slightly grown) box, along
    // the box's axes, as eight corners in layout coordinates
    // (math::box_corners's order).
    std::array<glm::dvec3, 8> corners{};
};

struct Scene {
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    std::vector<IndexRange> cells;                // per room: faces (with holes) and props
    std::vector<std::vector<DrawBatch>> batches;  // per room: cells[room] split by material state
    std::vector<CellObjects> objects;             // per room: the same, split for culling
    std::vector<SceneTexture> textures;           // each image and sampler once
    std::vector<CellOrigin> origins;              // per room: the origin of its vertices and its portals'
    std::vector<PortalMesh> portals;              // per portal, relative to its room's frame
    std::vector<PortalInfo> portal_info;          // per portal
    links::PortalLinks links;                     // M_AB per portal and the portals of each room, linked once
    // The dynamic props and the hand (walk::build_object_set): left out of
    // cells, objects and batches above, drawn per frame as instances.
    walk::ObjectSet object_set;
    std::vector<ObjectMesh> object_meshes;             // per object_set.props, then the hand (the last)
    std::vector<std::vector<layout::Volume>> volumes;  // per room: its volume portals, in file order
    // Per room, per volume: its target room's triangles that may lie inside
    // the volume, in pieces with their bounds (scene/volume_pieces.hpp).
    std::vector<std::vector<std::vector<VolumePiece>>> volume_pieces;
    // Under "lighting": "lights" (layout-format.md, "Lights"): every room's
    // light images at the layout's light_depth (lights::light_images), and
    // the layout with the lights that light frames (lights::light_bound),
    // for a renderer asked for another depth (View::light_depth).
    // "fixed": Lighting::Fixed, nothing else.
    layout::Lighting lighting = layout::Lighting::Fixed;
    int light_depth = layout::kDefaultLightDepth;  // the layout's, at most max_light_depth
    // The deepest light depth within lights::kMaxLightPaths paths and
    // lights::kMaxLightRects path rectangles (lights::LightBound::depth): a
    // frame asking for more (View::light_depth) is lit at this depth.
    int max_light_depth = layout::kMaxLightDepth;
    std::vector<lights::RoomLights> room_lights;
    std::shared_ptr<const layout::Layout> lit_layout;
    double exposure = 0.0;  // the layout's "exposure", EV (View::exposure replaces it)
};

// Builds the meshes of every room and portal box, and links the portals. The
// layout must be valid (from the loader); glTF props use the triangles the
// loader read.
Scene build_scene(const layout::Layout& layout, const links::PortalLinks& links);
// The same, linking the layout's portals itself (tests and tools; the program
// builds through session::Session, which links once).
Scene build_scene(const layout::Layout& layout);

}  // namespace impossible::scene
