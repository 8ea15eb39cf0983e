// Where each object of a frame is drawn (layout-format.md, "Moving props,
// hands and crossing objects"): the one rule the rasteriser and the tracer
// both follow for props that move or meet a door, and for tracked hands.
//
// A prop that neither moves nor meets a door of its room at rest with a
// part behind the door's plane is *static*: it stays part of its room's
// geometry, drawn as before (so layouts without such props render
// byte-identically; a prop that only touches a door from the front is cut
// to itself and has an empty image, which is what the static drawing shows). Every other prop,
// and each hand, is *dynamic*: each frame it becomes one or more
// ObjectInstance — its solid, placed in a cell by a rigid matrix, optionally
// cut by the planes of the doors it meets:
//   - in its current room, the part in front of each door A it meets
//     (d >= 0 for A);
//   - in A's target room B, its image M_AB · object, the part in front of
//     B's plane (d > 0 for B), one instance per door met.
// An object meets door A when its solid (a box's closed volume, a model's
// triangles) intersects A's closed rectangle (touching counts, within
// kMeetTolerance). Mirrors, windows and volumes cut nothing.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "layout/layout.hpp"
#include "links/portal_links.hpp"
#include "math/conventions.hpp"
#include "math/pose.hpp"
#include "math/view.hpp"

namespace impossible::walk {

// What an instance draws: a prop (by its listed room and index there) or a
// hand (0 left, 1 right).
enum class ObjectKind { Prop, Hand };

// At most this many doors cut one instance (an object meeting more uses the
// first ones, in the room's portal order; the spec leaves it undefined).
inline constexpr int kMaxCuts = 2;

struct ObjectCut {
    math::dvec4 plane{0.0, 0.0, 0.0, 1.0};  // in the cell's coordinates: dot(plane, (p, 1)) is d
    bool strict = false;                    // keep d > 0 (an image, B's plane) instead of d >= 0 (own room)
    int door = -1;                          // the portal whose plane it is
};

struct ObjectInstance {
    ObjectKind kind = ObjectKind::Prop;
    int listed_room = -1;  // Prop: the room it is listed in; Hand: -1
    int index = -1;        // Prop: its index in that room's props; Hand: 0 left, 1 right
    int cell = -1;         // the room it is drawn in
    // The object's own coordinates → the cell's coordinates. A prop's own
    // coordinates are the layout's as written (its box min/max, its placed
    // model triangles); a hand's are its frame (centred, x right, y up, z
    // back; HandShape).
    math::dmat4 to_cell{1.0};
    int cut_count = 0;
    std::array<ObjectCut, kMaxCuts> cuts{};
    bool image = false;  // drawn through a door (M_AB applied; cuts[0] is B's plane)
};

// Touching within this counts as meeting (times 1 + |door centre|).
inline constexpr double kMeetTolerance = 1e-9;

// What place_objects needs of a layout, copied once (a renderer's or a
// tracer's scene keeps one, so that a frame needs only its View): the
// dynamic props and their solids, the hand's solid, and every door.
struct ObjectSolid {
    bool is_box = true;
    math::dvec3 min{0.0}, max{0.0};      // a box, in its own coordinates
    std::vector<math::dvec3> triangles;  // a model: 3 corners a triangle, in its own coordinates
};

struct DynamicProp {
    int room = -1;   // listed room
    int index = -1;  // in that room's props
    math::dvec3 anchor{0.0};
    layout::Motion motion;
    ObjectSolid solid;  // in the layout's coordinates as written
};

struct ObjectDoor {
    math::PortalRect rect;
    int room = -1;              // the room it stands in
    int target = -1;            // the paired door
    math::dmat4 transfer{1.0};  // M_AB
};

struct ObjectSet {
    std::vector<std::vector<bool>> dynamic;    // per room, per prop (layout order): drawn as instances
    std::vector<DynamicProp> props;            // the dynamic props, room order then listed order
    ObjectSolid hand;                          // in the hand's frame (HandShape)
    std::vector<ObjectDoor> portals;           // per portal of the layout; target -1 for non-doors
    std::vector<std::vector<int>> room_doors;  // per room: its doors, in file order
    // The layout's rooms and portals without props or images: what a
    // walk::Walker needs to walk props and hands (shared, so the set copies
    // cheaply and the walkers' pointer stays valid when it moves).
    std::shared_ptr<const layout::Layout> walk_layout;
    std::shared_ptr<const links::PortalLinks> walk_links;  // link_portals(*walk_layout), made once
};

ObjectSet build_object_set(const layout::Layout& layout, const links::PortalLinks& links);

// Per room, per prop (in the layout's order): whether the prop is dynamic
// (the same as build_object_set(...).dynamic).
std::vector<std::vector<bool>> dynamic_props(const layout::Layout& layout, const links::PortalLinks& links);

// A moving prop at a time: its current room and its mapping W from physical
// (listed place plus offset) to virtual coordinates (layout-format.md,
// "Moving props"). Exact and independent of how the time was reached: the
// anchor walks the keys' polyline from t = 0, key to key, then to `time`.
// Each call walks the keys from t = 0; a PropWalks (prop_walks.hpp) gives
// the same states, bit for bit, walking only the keys passed since its last
// time, for whoever walks successive frames.
struct PropState {
    int room = -1;
    math::dmat4 w{1.0};
    math::dvec3 offset{0.0};  // the physical offset at `time`
};
// `prop` indexes set.props. A looping motion walks every whole period up to
// `time` (then the rest), except that once its state (room and W) repeats
// one it had after an earlier period — the usual case, a prop that goes
// through a door and back — the periods repeat and are skipped; the states
// of the first kMaxRememberedPeriods periods are remembered for this.
// A motion that never repeats (a loop through doors that turn it a little
// more each period) walks at most kMaxWalkedPeriods whole periods, and at
// most kMaxWalkedKeySteps walker steps in them (so a 10,000-key loop walks
// 100 periods); past them the remaining periods are not walked
// (docs/bounded-work.md).
inline constexpr std::size_t kMaxRememberedPeriods = 16;
inline constexpr double kMaxWalkedPeriods = 1e5;
inline constexpr double kMaxWalkedKeySteps = 1e6;
PropState walk_prop(const ObjectSet& set, int prop, double time);

// A hand placed for a frame: its room and the transform of its frame into
// that room's coordinates, found by walking the straight segment from the
// head centre (in `head_room`) to the hand's virtual position with the
// crossing rule (layout-format.md, "Hands").
struct HandState {
    int room = -1;
    math::dmat4 to_cell{1.0};
    std::vector<int> teleports;  // doors passed on the way from the head
};
HandState place_hand(const ObjectSet& set, int head_room, const math::dvec3& head_position, const math::HeadPose& hand);

// Every dynamic object of a view (its time, head and hands), as instances:
// each dynamic prop walked to view.time, each hand placed from
// view.head.position in view.room, each then cut and imaged by the doors it
// meets. Deterministic: props in set.props order, then the left and the
// right hand; for each, its own-room instance first, then its images in the
// order of the doors met. No hands: none drawn. The props are walked by
// `walks` when it is given and made for `set` (the same result, walking only
// the keys passed since its last time), else each from t = 0.
class PropWalks;
std::vector<ObjectInstance> place_objects(const ObjectSet& set, const math::View& view, PropWalks* walks = nullptr);

}  // namespace impossible::walk
