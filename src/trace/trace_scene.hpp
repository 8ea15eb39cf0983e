// The reference tracer's own view of a layout: per room, the surfaces a ray
// can hit, in double precision and in the layout's coordinates, plus each
// portal's frame and transfer matrix. Built once from a layout::Layout and
// read-only afterwards (safe to share between threads).
//
// Deliberately independent of the rasteriser: nothing here comes from
// src/scene's meshes or src/render. Surfaces are analytic (axis-aligned
// rectangles, boxes, triangles), and the holes that portals cut in room faces
// are found again here from the spec's rule rather than taken from the loader.
#pragma once

#include <array>
#include <memory>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

#include "base/result.hpp"
#include "layout/layout.hpp"
#include "layout/room_shape.hpp"
#include "math/conventions.hpp"
#include "math/portal.hpp"
#include "math/view.hpp"
#include "walk/objects.hpp"

namespace impossible::trace {

using math::dmat3;
using math::dmat4;
using math::dvec3;
using math::dvec4;

// A rectangle in the plane p[axis] == coord, spanning [lo, hi] on the other
// two axes (lo[axis] and hi[axis] are not read). It is visible only from the
// side its normal points to: normal = sign · unit(axis), sign = ±1.
struct AxisRect {
    int axis = 0;
    double coord = 0.0;
    double sign = 1.0;
    dvec3 lo{0.0};
    dvec3 hi{0.0};
};

// A face of a room, seen from inside (its normal points into the room).
struct RoomFace {
    AxisRect rect;
    layout::Face face = layout::Face::Floor;
    dvec3 color{0.8};
    std::vector<int> holes;  // portals (indices into Scene::portals) cutting a hole here
    // Multiplies `color` where set: read at shading::room_texture_uv(face, p,
    // texture_size) with the default sampler (docs/tracer.md, "Materials
    // and textures"), or on a prism's wall at layout::wall_uv's coordinates.
    std::shared_ptr<const image::Pixels> texture;
    double texture_size = 1.0;
    // A prism room's wall (PrismFace): its index, and its face frame's origin
    // and s axis, along which its texture runs (layout::wall_uv); -1 otherwise.
    int wall = -1;
    dvec3 wall_origin{0.0};
    dvec3 wall_s_axis{0.0};
};

// A face of a prism room (layout-format.md, "Rooms of any shape"), seen from
// inside: its colour, holes and texture as a box room's face has them
// (`surface`, whose rect is not read), and its unit normal into the room.
// Where it lies is its index's: 0 the floor and 1 the ceiling, at height
// `y` over the floor polygon, 2 + i wall i, from corner i to corner i + 1
// (PrismShape::corners) between the floor and the ceiling.
struct PrismFace {
    RoomFace surface;
    layout::FaceFrame frame;  // the face's plane and outline (prism_hole_face reads it)
    dvec3 normal{0.0};
    double y = 0.0;  // the floor's or the ceiling's height
};

// A prism room's faces (prism_faces.hpp intersects them). Walls meet the
// ray's line where it separates their two corners (in x, z), each corner's
// side computed once per ray, so two walls that share a corner leave no gap
// between them; the floor and the ceiling reach `tolerance` past the
// polygon's edges, so none opens between them and a wall either.
struct PrismShape {
    std::vector<glm::dvec2> corners;  // the floor polygon (x, z) in file order
    double winding = 1.0;             // +1: counter-clockwise in (x, z) (math::signed_area > 0), else -1
    glm::dvec2 lo{0.0}, hi{0.0};      // the polygon's bounding rectangle
    double y0 = 0.0, y1 = 0.0;        // floor and ceiling heights
    double tolerance = 0.0;           // 1e-9 · (1 + the largest |corner coordinate|)
    std::vector<PrismFace> faces;     // in layout face order: floor, ceiling, walls
};

// A prop box, visible from outside.
struct PropBox {
    dvec3 min{0.0};
    dvec3 max{0.0};
    dvec3 color{0.8};
};

// A glTF material as the tracer reads it (assets::Material, with its
// texture looked up). A triangle without one (PropTriangle::material < 0)
// is opaque, one-sided and untextured.
struct PropMaterial {
    double alpha = 1.0;         // baseColorFactor's alpha (its rgb is PropTriangle::color)
    assets::Texture texture;    // image null: none (the texel is white)
    bool double_sided = false;  // hit from both sides, the back's normal reversed
    bool mask = false;          // alphaMode MASK: alpha below alpha_cutoff is no surface
    double alpha_cutoff = 0.5;
};

// A glTF triangle placed in the layout: counter-clockwise seen from its front.
// Its base colour at barycentrics (w0, u, v) is color · COLOR_0 · texel (at
// the blended uv), its alpha the material's · COLOR_0's · texel's.
struct PropTriangle {
    std::array<dvec3, 3> position;
    int material = -1;  // into the room's SceneRoom::materials; -1: none (see PropMaterial)
    // Only what a ray may need before it knows it hits lies next to the
    // positions, which every ray reads; the rest is read for hits only.
    std::array<dvec3, 3> normal;                                            // unit vertex normals
    dvec3 color{0.8};                                                       // the material's base colour factor (rgb)
    std::array<dvec4, 3> vertex_color{dvec4(1.0), dvec4(1.0), dvec4(1.0)};  // COLOR_0
    std::array<glm::dvec2, 3> uv{};
};

// A door, mirror or window (layout-format.md, "Mirrors and windows"). A door
// is a box; a mirror or a window is only its front rectangle, one-sided,
// facing +n (it always fills a hole, so hit_room_face meets it).
struct ScenePortal {
    math::PortalRect rect;
    dvec3 right{0.0};  // u × n
    int room = -1;     // the room it belongs to
    int target = -1;   // the paired portal; -1 for a mirror
    layout::PortalKind kind = layout::PortalKind::Door;
    dvec3 tint{1.0};              // mirror, window: multiplies what is seen through or in it
    double reflectance = 0.0;     // window: the reflection's share r
    dmat4 to_local{1.0};          // layout → portal frame (x right, y up, z normal)
    dmat4 transfer{1.0};          // M_AB, onto the target portal (door, window)
    dmat4 reflection{1.0};        // M_P, the reflection in the plane (mirror, window)
    double clip_tolerance = 0.0;  // 1e-9 · (1 + |centre|): "strictly in front" of this plane
    dvec4 plane{0.0};             // math::portal_plane(rect): the clip plane it sets
    bool in_hole = false;         // fills a hole of one of its room's faces
};

// A node of a room's bounding-volume hierarchy over its triangles or its
// boxes (trace/bvh.hpp). The box holds every item below, padded (bvh.cpp).
// Nodes are stored depth-first: an inner node's first child follows it.
struct BvhNode {
    dvec3 lo{0.0};
    dvec3 hi{0.0};
    int first = 0;  // leaf: its first entry in Bvh::order; inner: the second child's index
    int count = 0;  // leaf: its number of items (> 0); inner: 0
};

struct Bvh {
    std::vector<BvhNode> nodes;  // nodes[0] is the root; none: no tree
    std::vector<int> order;      // indices into the items (SceneRoom::triangles or boxes), leaf after leaf
    std::vector<int> slivers;    // triangles tested on every ray, outside the tree (bvh.cpp); boxes: none
};

// A volume portal (layout-format.md, "Volume portals"): inside the box,
// the room `target` shows instead of the room it stands in.
struct SceneVolume {
    dvec3 center{0.0};
    dvec3 right{1, 0, 0}, up{0, 1, 0}, normal{0, 0, 1};  // r = u × n, u, n
    dvec3 half{0.0};                                     // width / 2, height / 2, depth / 2
    double tolerance = 0.0;                              // 1e-9 · (1 + |centre|)
    int target = -1;                                     // index into Scene::rooms
    dvec3 tint{1.0};
    // The closed box, widened by the tolerance (frame_objects.cpp).
    bool contains(const dvec3& p) const;
};

// Prop surfaces: a room's static props, or a dynamic object's surfaces in
// its own coordinates (SceneObject).
struct PropSurfaces {
    std::vector<PropBox> boxes;
    std::vector<PropTriangle> triangles;
    std::vector<PropMaterial> materials;  // those the triangles name, by PropTriangle::material
    // Built by prepare_scene over `triangles`, and over `boxes` when there
    // are more than a leaf's worth. Without nodes the tracer scans them one
    // by one; the tests clear them to compare the two.
    Bvh bvh;
    Bvh box_bvh;
};

// A room: its faces, and as PropSurfaces its static props only (a dynamic
// one, walk/objects.hpp, is a SceneObject, placed anew each frame).
struct SceneRoom : PropSurfaces {
    std::array<RoomFace, layout::kFaceCount> faces;  // a box room's, in layout::Face order
    PrismShape prism;                                // a prism room's (faces not empty; `faces` then unused)
    std::vector<int> portals;                        // indices into Scene::portals
    // Those of `portals` with more to hit than a hole's front, which the
    // faces meet (hit_room_face): free-standing portals and doors, whose
    // inner faces an eye in the box's column sees (hit_portal_box).
    std::vector<int> box_portals;
    double checker = 0.0;              // checker side for the faces, 0: plain
    std::vector<SceneVolume> volumes;  // its volume portals, in file order
    // Under "lighting": "lights" (Scene::lit): the room's ambient light and
    // its lights that light frames (lights::lit_lights), in its own
    // coordinates (layout-format.md, "Lights").
    dvec3 ambient{0.0};
    std::vector<layout::Light> lights;
};

// A dynamic object's surfaces (a prop that moves or meets a door, or the
// hand; walk/objects.hpp) in its own coordinates: a prop's are the layout's
// as written, the hand's its frame (HandShape).
struct SceneObject : PropSurfaces {};

// A door's cut of a placed object (walk::ObjectCut), in the cell's
// coordinates: an image keeps d > tolerance, its own room d ≥ -tolerance,
// with the door's clip tolerance 1e-9 · (1 + |centre|).
struct ObjectCutPlane {
    dvec4 plane{0.0, 0.0, 0.0, 1.0};
    bool strict = false;
    double tolerance = 0.0;
};

// A dynamic object placed in a cell for one frame (walk::ObjectInstance).
struct PlacedObject {
    int prop = -1;  // index into Scene::props; -1: the hand
    int cell = -1;
    dmat4 to_cell{1.0};    // rigid: own coordinates → the cell's
    dmat4 from_cell{1.0};  // its inverse
    dmat3 rotation{1.0};   // to_cell's rotation, for normals
    int cut_count = 0;
    std::array<ObjectCutPlane, walk::kMaxCuts> cuts{};
};

// A frame's dynamic objects, grouped by cell.
struct FrameObjects {
    std::vector<PlacedObject> placed;  // by cell, in place_objects' order within one
    std::vector<int> first;            // per room r: placed[first[r], first[r + 1]); empty: none at all
    std::span<const PlacedObject> in_room(int room) const {
        if (first.empty()) return {};
        return std::span<const PlacedObject>(placed).subspan(first[room], first[room + 1] - first[room]);
    }
};

struct Scene {
    std::vector<SceneRoom> rooms;
    std::vector<ScenePortal> portals;
    // The layout's moving and crossing objects (walk::build_object_set) and
    // their surfaces: props[i] is objects.props[i]'s, `hand` each hand's.
    walk::ObjectSet objects;
    std::vector<SceneObject> props;
    SceneObject hand;
    std::vector<std::vector<int>> prop_object;  // per room, per listed prop: its index in `props`, or -1
    // The objects at time 0 without hands, for rays traced without a frame's.
    FrameObjects rest;
    // "lighting": "lights": surfaces are lit by their room's ambient and the
    // light paths of light_paths.hpp, at most `light_depth` portals long
    // (the layout's; RayLimits::light_depth may replace it). Otherwise the
    // fixed model of shading/shading.hpp. Either depth is lowered to
    // max_light_depth, the deepest within lights::kMaxLightPaths paths and
    // lights::kMaxLightRects path rectangles, and the rooms keep only the
    // lights that light frames, as the rasteriser cuts them
    // (lights::light_bound).
    bool lit = false;
    int light_depth = layout::kDefaultLightDepth;
    int max_light_depth = layout::kMaxLightDepth;
    double exposure = 0.0;  // the layout's "exposure", EV (View::exposure replaces it)
};

// The dynamic objects of a view: its props at view.time and its hands
// (walk::place_objects, the hands walked from view.head in view.room; none
// where view.room is out of range), grouped by cell.
FrameObjects place_frame_objects(const Scene& scene, const math::View& view);

// Corners of a hole may be this far from the face's plane (layout-format.md).
inline constexpr double kHolePlaneTolerance = 1e-4;

// The face `face` of a room box, normal inwards.
AxisRect room_face_rect(const dvec3& room_min, const dvec3& room_max, layout::Face face);

// Whether the portal's rectangle cuts a hole in the face: all four corners
// within kHolePlaneTolerance of the face's plane and inside the face (same
// tolerance), and the normal pointing into the room.
bool cuts_hole(const AxisRect& face, const math::PortalRect& rect);

// Builds the tracer's scene. The layout must be valid (as the loader returns
// it); portal rooms out of range, targets out of range for a door or a
// window (a mirror's target is not read), a volume whose room or target is
// out of range or whose target has portals or volumes, and a model's
// material or texture indices out of range are an error naming the portal,
// volume or model.
Result<Scene> prepare_scene(const layout::Layout& layout, const links::PortalLinks& links);
// The same, linking the layout's portals itself (tests and tools; the program
// prepares through session::Session, which links once).
Result<Scene> prepare_scene(const layout::Layout& layout);

}  // namespace impossible::trace
