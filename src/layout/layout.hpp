// A loaded, validated layout (../shared/spec/layout-format.md, version 1).
//
// Plain data in double precision, in the file's own (virtual) coordinates:
// metres, right-handed, +Y up. Everything here has already been checked by the
// loader: ids are unique, portals are paired, vectors are unit length, colours
// are in 0..1, and glTF paths are resolved against the layout file.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "assets/file_read.hpp"
#include "assets/model.hpp"
#include "image/pixels.hpp"
#include "math/portal.hpp"
#include "math/view_limits.hpp"

namespace impossible::layout {

// Face order used everywhere (room colours, meshes, tracer hits): a box
// room's six faces. A prism room (layout-format.md, "Rooms of any shape") has
// floor and ceiling at the same indices and then its walls: face 2 + i is
// wall i (room_shape.hpp, face_count).
enum class Face : int { Floor = 0, Ceiling, NegX, PosX, NegZ, PosZ };
inline constexpr int kFaceCount = 6;
inline constexpr std::array<const char*, kFaceCount> kFaceNames = {"floor", "ceiling", "-x", "+x", "-z", "+z"};

// layout-format.md, "Moving props": the prop's offset from where the layout
// puts it at time t (linear between keys).
struct MotionKey {
    double t = 0.0;
    glm::dvec3 offset{0.0};
};

struct Motion {
    // Empty: the prop does not move. Otherwise keys[0].t == 0 and the times
    // increase strictly (the loader checks).
    std::vector<MotionKey> keys;
    bool loop = false;  // repeat with the period keys.back().t
};

struct BoxProp {
    glm::dvec3 min{0.0};
    glm::dvec3 max{0.0};
    glm::dvec3 color{0.8};  // defaults to the room's `color`
    std::string id;         // optional ("" none); unique among the layout's props
    Motion motion;
};

struct GltfProp {
    std::string path;           // as written in the file
    std::string resolved_path;  // resolved against the layout file's directory
    glm::dvec3 position{0.0};
    double yaw_deg = 0.0;
    double scale = 1.0;
    std::vector<assets::ModelTriangle> triangles;  // read by the loader
    std::vector<assets::Material> materials;       // those the triangles use, by ModelTriangle::material
    std::vector<assets::Texture> textures;         // those the materials use, by Material::texture
    std::string id;                                // optional ("" none); unique among the layout's props
    Motion motion;
    std::vector<assets::ModelLight> lights;       // read by the loader; kept only under "lighting": "lights"
    std::vector<std::string> directional_lights;  // the model's, dropped with a warning (add_prop_lights)
};

// The prop's model → layout transform: scale, then yaw about +Y, then move.
glm::dvec3 place_model_point(const GltfProp& prop, const glm::dvec3& p);
glm::dvec3 place_model_normal(const GltfProp& prop, const glm::dvec3& n);

using Prop = std::variant<BoxProp, GltfProp>;

const std::string& prop_id(const Prop& prop);
const Motion& prop_motion(const Prop& prop);
// The point that walks the motion path: a box's centre, a model's `position`.
glm::dvec3 prop_anchor(const Prop& prop);

// Top-level `hands` (layout-format.md, "Moving props, hands and crossing
// objects"): how a tracked hand is drawn, centred on its position, in the
// hand's frame (x right, y up, z back, as a head pose's rotation columns).
struct HandShape {
    // A glTF model (position 0, yaw 0, its `scale`), turned by the hand's
    // orientation so that the model's -Z points along the hand's forward;
    // none: the box.
    std::optional<GltfProp> model;
    glm::dvec3 box{0.08, 0.04, 0.16};  // width (x), height (y), depth (z), metres
    glm::dvec3 color{0.85, 0.70, 0.60};
};

// layout-format.md, "Volume portals": inside the box (centred on
// rect.center; rect.width along r, rect.height along u, rect.depth along n)
// the room `target_room` shows instead of `room`. Listed in the layout's
// `portals` array with kind "volume", kept apart from the paired portals.
struct Volume {
    std::string id;
    int room = -1;          // index into Layout::rooms
    math::PortalRect rect;  // depth = the box's extent along the normal (centred, not behind)
    int target_room = -1;   // index into Layout::rooms; a room without portals
    glm::dvec3 tint{1.0};
};

// layout-format.md, "Lights": a point light, or a spot with a cone.
struct Spot {
    glm::dvec3 direction{0.0, -1.0, 0.0};  // unit (normalised on load)
    double inner_deg = 0.0;
    double outer_deg = 45.0;  // > inner_deg, <= 90
};

struct Light {
    glm::dvec3 position{0.0};  // strictly inside its room
    glm::dvec3 color{1.0};     // 0..1 per channel
    double intensity = 1.0;    // candela (KHR_lights_punctual's units)
    double range = 0.0;        // where it fades to nothing; 0: no limit
    std::optional<Spot> spot;  // none: a point light
    // The glTF prop (index into its room's props) whose KHR_lights_punctual
    // light this is, posed with the prop at rest; -1: written in `lights`.
    int prop = -1;
};

// Top-level `lighting`: the built-in light of every room, or each room's
// ambient and lights (with light passing through portals).
enum class Lighting { Fixed, Lights };

inline constexpr int kDefaultLightDepth = 2;
inline constexpr int kMaxLightDepth = math::limits::kMaxLightDepth;
inline const glm::dvec3 kDefaultAmbient{0.1, 0.1, 0.1};

struct Room {
    std::string id;
    // A box room's corners; a prism room's bounding box (its floor polygon's
    // x and z range, its `y` range).
    glm::dvec3 min{0.0};
    glm::dvec3 max{0.0};
    // A prism room's floor polygon, corners [x, z] in file order (either
    // winding; room_shape.hpp reads it); empty for a box room. A prism's
    // floor is at min.y and its ceiling at max.y.
    std::vector<glm::dvec2> floor;
    // Per face, in face order (kFaceCount for a box, 2 + walls for a prism).
    std::vector<glm::dvec3> face_color = std::vector<glm::dvec3>(kFaceCount);  // `color` with `face_colors` applied
    double checker = 0.0;                                                      // 0: plain
    // `textures` with `all` applied: a face's image (null: none), multiplied
    // by its colour, one tile per texture_size metres from whole multiples of
    // it in layout coordinates (room_texture_uv in shading.hpp orients it);
    // on a prism's wall tiles run along the wall (room_shape.hpp, wall_uv).
    std::vector<std::shared_ptr<const image::Pixels>> face_texture =
        std::vector<std::shared_ptr<const image::Pixels>>(kFaceCount);  // RGBA
    double texture_size = 1.0;
    std::vector<Prop> props;
    // Only under "lighting": "lights" (layout-format.md, "Lights").
    glm::dvec3 ambient = kDefaultAmbient;
    std::vector<Light> lights;  // `lights` in file order, then those of its glTF props in prop order
};

// layout-format.md, "Mirrors and windows": a door is walked through, a mirror
// reflects its own room, a window shows its partner's room blended with the
// reflection of its own.
enum class PortalKind { Door, Mirror, Window };

// "door", "mirror" or "window", as written in a layout file.
const char* kind_name(PortalKind kind);

struct Portal {
    std::string id;
    int room = -1;          // index into Layout::rooms
    math::PortalRect rect;  // normal unit into the room; up made orthogonal; depth 0 unless a door
    int target = -1;        // index into Layout::portals; -1 for a mirror
    PortalKind kind = PortalKind::Door;
    glm::dvec3 tint{1.0};      // mirrors and windows: multiplies the light through or back
    double reflectance = 0.1;  // windows: the reflection's share r
    // The face of its room in which the rectangle cuts a hole (a Face as int;
    // for a prism room floor, ceiling or 2 + wall), or -1 for a portal standing free in the room (layout-format.md, "The
    // portal box"). The hole has exactly the rectangle's size.
    int hole_face = -1;
};

// The tracked floor: a rectangle, or a simple polygon (layout-format.md, top
// level). `min`/`max` are always its bounding box ([x, z]); `polygon` holds
// the outline as written (either winding), or is empty for a rectangle.
struct PlayArea {
    glm::dvec2 min{0.0};  // [x, z]
    glm::dvec2 max{0.0};
    std::vector<glm::dvec2> polygon{};  // empty: the rectangle min..max
};

// The outline of a play area: its polygon, or the rectangle's four corners
// (counter-clockwise in x, z).
std::vector<glm::dvec2> outline(const PlayArea& area);

struct Start {
    int room = -1;
    glm::dvec3 position{0.0};
    double yaw_deg = 0.0;
};

// layout-format.md, "Changes while walking": when a change is armed. Every
// part is optional; the loader makes sure at least one is set.
struct ChangeWhen {
    int enter = -1;              // index into Layout::rooms: the head is in that room; -1: no condition
    int after = -1;              // index of an earlier change in Layout::changes, made at an earlier frame; -1: none
    std::optional<double> time;  // seconds: the frame's time is at least this
};

// A re-pairing of doors, made where neither eye sees any door it affects.
struct Change {
    std::string id;
    ChangeWhen when;
    // Indices into Layout::portals, doors only, each door at most once in a
    // change; after the change the two doors of each pair target each other.
    std::vector<std::array<int, 2>> pairs;
};

struct Layout {
    std::string source;  // file path, or a name such as "<default>"
    std::string name;
    std::optional<PlayArea> play_area;
    Start start;
    std::vector<Room> rooms;
    std::vector<Portal> portals;  // doors, mirrors and windows (volumes are in `volumes`)
    std::vector<Volume> volumes;  // in file order
    std::vector<Change> changes;  // in file order (layout-format.md, "Changes while walking")
    HandShape hands;
    Lighting lighting = Lighting::Fixed;
    int light_depth = kDefaultLightDepth;  // 0..kMaxLightDepth; read only under Lighting::Lights
    // "exposure" (EV, math::limits::kExposure): each surface's colour times
    // 2^exposure before its clamp; View::exposure replaces it.
    double exposure = 0.0;
    // The warnings about what a glTF model holds that is drawn otherwise than
    // the file says (alphaMode BLEND, a dropped light), "FILE:LINE:COLUMN:
    // message" each; render and trace print them as validate does.
    std::vector<std::string> model_warnings;
    // Every file the loader read besides the layout itself, in order: room
    // textures, glTF models and their buffers and images.
    std::vector<assets::FileRead> files_read;
};

// One problem found in a layout. line/column are 1-based; 0 where unknown.
struct Diagnostic {
    std::string file;
    int line = 0;
    int column = 0;
    std::string message;

    // "FILE:LINE:COLUMN: message", or "FILE: message" without a position.
    std::string str() const;
};

struct LoadResult {
    std::optional<Layout> layout;      // set exactly when errors is empty
    std::vector<Diagnostic> errors;    // every problem found, in file order
    std::vector<Diagnostic> warnings;  // legal but suspicious, in file order
    // Those of `warnings` that every command loading the layout prints (a
    // door whose normal points out of its room), not only validate.
    std::vector<Diagnostic> loud_warnings;
};

// Reads and validates a layout file. Never throws for bad input.
LoadResult load_layout_file(const std::string& path);

// Parses layout text; `source` names it in diagnostics and `base_dir`
// resolves relative glTF paths (glTF files must exist and parse).
LoadResult load_layout_text(const std::string& text, const std::string& source, const std::string& base_dir);

// Finds a room by id; -1 if absent.
int find_room(const Layout& layout, const std::string& id);

// What `impossible validate` reports about a valid layout (cli.md).
struct Summary {
    int rooms = 0;
    int portals = 0;
    int pairs = 0;  // linked portal pairs, doors and windows
    int door_pairs = 0;
    int window_pairs = 0;
    int mirrors = 0;  // mirrors have no pair
    // Ids of the rooms whose floor rectangle [x, z] is not inside the play
    // area, in file order; empty without a play area.
    std::vector<std::string> rooms_outside_play_area;
    double floor_area = 0.0;                // summed floor areas of the rooms, m²
    std::optional<double> play_area_area;   // m², absent without a play area
    std::optional<double> expansion_ratio;  // floor_area / play_area_area
    int textured_faces = 0;                 // room faces with a texture
    int images = 0;                         // distinct decoded images: room textures and glTF props' textures
    int volumes = 0;                        // volume portals (not counted in `portals`)
    int moving_props = 0;                   // props with a motion
};

Summary summarize(const Layout& layout);

// A few lines of "key: value" text for the validate command.
std::string summary_text(const Layout& layout, const Summary& summary);

}  // namespace impossible::layout
