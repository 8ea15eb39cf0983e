// The parts of the layout reader (internal). Each reads its part of the
// JSON, reports every problem through the Checker, and keeps what it could
// read so later checks (pairs, holes) can run without cascading errors.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "assets/asset_cache.hpp"
#include "assets/gltf_model.hpp"
#include "base/result.hpp"
#include "layout/checker.hpp"
#include "layout/layout.hpp"

namespace impossible::layout::detail {

struct RoomDraft {
    Room room;
    Path path;
    bool has_id = false;
    // The shape was read and is valid: a box (min/max, max > min), or a
    // prism (floor and y, see read_rooms.cpp).
    bool shape_ok = false;
    // Written with `floor` (layout-format.md, "Rooms of any shape"): its face
    // keys are a prism's. room.floor holds the corners as soon as they could
    // be read, valid or not, so that "wallN" can be checked against them.
    bool prism = false;
};

struct PortalDraft {
    Portal portal;
    Path path;
    std::optional<std::string> room_id;
    std::optional<std::string> target_id;
    bool has_id = false;
    bool rect_ok = false;   // center, normal, up, width, height, depth read
    bool has_kind = false;  // "kind" is written
    bool kind_ok = true;    // "kind" is absent (a door) or one of the four kinds
    // "kind": "volume" (layout-format.md, "Volume portals"): kept apart from
    // the paired portals; `target_id` names a room, found by link_volumes.
    bool volume = false;
    int target_room = -1;
};

// The props' ids seen so far in the layout, each with where it was first
// used ("rooms[0].props[2]"): prop ids are unique in the whole layout.
using PropIds = std::map<std::string, std::string>;

// A room's `face_colors` and `textures` (room_faces.cpp), into room.face_color
// (already filled with `color`) and room.face_texture (already sized): box
// keys for a box room, "walls" and "wallN" for a prism.
void read_face_colors(Checker& check, const Path& at, const json& value, RoomDraft& draft);
void read_textures(Checker& check, const Path& at, const json& value, assets::AssetCache& models, RoomDraft& draft);

std::vector<RoomDraft> read_rooms(Checker& check, const Path& at, const json& rooms, assets::AssetCache& models);

void read_props(Checker& check, const Path& at, const json& props, const glm::dvec3& room_colour,
                assets::AssetCache& models, PropIds& ids, std::vector<Prop>& out);

// Loads the glTF file named by the string `gltf` (at `gltf_at`) into `prop`'s
// path, triangles, materials and textures; `instances` copies count towards
// the layout's triangle budget. False if it cannot (reported).
bool load_gltf_model(Checker& check, const Path& gltf_at, const json& gltf, assets::AssetCache& models,
                     std::size_t instances, GltfProp& prop);

// Top-level `hands`: a box (`box` [W, H, D], `color`) or a glTF model
// (`gltf`, `scale`), exactly one. Nothing if it is wrong (reported).
std::optional<HandShape> read_hands(Checker& check, const Path& at, const json& value, assets::AssetCache& models);

// layout-format.md, "Lights": the top-level `lighting` and `light_depth`
// into `layout`, each room's `ambient` and `lights` into `rooms` (which
// read_rooms made from the same `rooms` list). Under "fixed" the room fields
// and light_depth are errors (read_lights.cpp).
void read_lighting(Checker& check, const json& root, std::vector<RoomDraft>& rooms, Layout& layout);

// A non-zero vector (reported otherwise), not normalised.
std::optional<glm::dvec3> read_direction(Checker& check, const Path& at, const json& value);

// A unit vector within limits::kUnitTolerance, normalised, or nothing
// (reported): a portal's normal, a spot's direction.
std::optional<glm::dvec3> read_normal(Checker& check, const Path& at, const json& value);

// Farther than 1e-9 · (1 + |p|) from every face of the room (its box, or its
// prism's floor, ceiling and walls).
bool strictly_inside(const Room& room, const glm::dvec3& p);

// Once everything is read without error: under "lights" (`lit`) each glTF
// prop's lights, posed with the prop at rest, appended to its room's lights
// in prop order (one outside its room is an error at the prop); otherwise
// the props' lights are dropped. A hand model's lights are always dropped
// (prop_lights.cpp).
void add_prop_lights(Checker& check, std::vector<RoomDraft>& rooms, bool lit, std::optional<HandShape>& hands);

// A warning for each light inside a prop of its room (a box, or a model's
// bounding box; a model's own lights are not checked against it).
void warn_lights_in_props(Checker& check, const std::vector<RoomDraft>& rooms);

std::vector<PortalDraft> read_portals(Checker& check, const Path& at, const json& portals);

// Resolves each portal's room and target, and checks the pairs. Without
// `rooms_known` (the room list had errors) an unknown room id is not reported.
void pair_portals(Checker& check, std::vector<PortalDraft>& portals, const std::vector<RoomDraft>& rooms,
                  bool rooms_known);

// The index in Layout::portals of each portal draft: the doors, mirrors and
// windows in file order, the volumes left out (-1).
std::vector<int> paired_indices(const std::vector<PortalDraft>& portals);

// layout-format.md, "Changes while walking": the top-level `changes`, read
// once pair_portals and link_start have run (read_changes.cpp), each pair's
// doors as indices into Layout::portals (paired_indices). Without
// `rooms_known` an unknown room id is not reported, nor an unknown change id
// without `ids_reliable` (no object repeats a key). If no error has been
// reported by then, warnings for a change that can never happen and for one
// that changes nothing.
std::vector<Change> read_changes(Checker& check, const Path& at, const json& changes,
                                 const std::vector<PortalDraft>& portals, const std::vector<RoomDraft>& rooms,
                                 int start_room, bool rooms_known, bool ids_reliable);

// Volumes (layout-format.md, "Volume portals"): each target names a room
// without portals of its own (of any kind, volumes included), and the
// volumes of a room do not overlap; a volume wholly outside its room gets a
// warning.
void link_volumes(Checker& check, std::vector<PortalDraft>& portals, const std::vector<RoomDraft>& rooms,
                  bool rooms_known);

// The hole rule (layout-format.md, "The portal box"): sets hole_face, and
// reports rectangles partly inside a face, overlapping holes, and mirrors
// and windows that stand free (they must lie in a face of their room).
void check_holes(Checker& check, std::vector<PortalDraft>& portals, const std::vector<RoomDraft>& rooms);

// A door that lies in a face of its room (its plane, inside the face) with
// its normal pointing out of the room makes no hole: it stands free, hidden
// in the face, and is never walked through. A loud warning at its `normal`
// with the normal to write instead (door_normal.cpp).
void warn_doors_facing_out(Checker& check, const std::vector<PortalDraft>& portals,
                           const std::vector<RoomDraft>& rooms);

// Index of each id (the first, where ids repeat).
template <class Draft>
std::map<std::string, int> index_by_id(const std::vector<Draft>& drafts) {
    std::map<std::string, int> out;
    for (std::size_t i = 0; i < drafts.size(); ++i) {
        const auto& item = drafts[i];
        if (!item.has_id) continue;
        if constexpr (std::is_same_v<Draft, RoomDraft>) {
            out.emplace(item.room.id, static_cast<int>(i));
        } else {
            out.emplace(item.portal.id, static_cast<int>(i));
        }
    }
    return out;
}

}  // namespace impossible::layout::detail
