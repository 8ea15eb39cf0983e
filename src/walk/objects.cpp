// The frame's objects (objects.hpp): dynamic props walked to the frame's
// time, hands placed from the head, each cut and imaged by the doors it meets.
#include "walk/objects.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <type_traits>
#include <variant>

#include "math/pose.hpp"
#include "walk/object_meet.hpp"
#include "walk/prop_walks.hpp"
#include "walk/walker.hpp"

namespace impossible::walk {

namespace {

using math::dmat4;
using math::dvec3;
using math::dvec4;

ObjectSolid solid_of(const layout::Prop& prop) {
    ObjectSolid s;
    if (const auto* box = std::get_if<layout::BoxProp>(&prop)) {
        s.min = box->min;
        s.max = box->max;
        return s;
    }
    const auto& model = std::get<layout::GltfProp>(prop);
    s.is_box = false;
    s.triangles.reserve(3 * model.triangles.size());
    for (const assets::ModelTriangle& t : model.triangles)
        for (const dvec3& p : t.position) s.triangles.push_back(layout::place_model_point(model, p));
    return s;
}

ObjectSolid hand_solid(const layout::HandShape& hands) {
    ObjectSolid s;
    if (!hands.model) {
        s.min = -0.5 * hands.box;
        s.max = 0.5 * hands.box;
        return s;
    }
    s.is_box = false;
    for (const assets::ModelTriangle& t : hands.model->triangles)
        for (const dvec3& p : t.position) s.triangles.push_back(layout::place_model_point(*hands.model, p));
    return s;
}

// The rooms and portals only: what a Walker reads.
std::shared_ptr<const layout::Layout> walk_layout_of(const layout::Layout& layout) {
    auto copy = std::make_shared<layout::Layout>();
    copy->source = layout.source;
    copy->start = layout.start;
    copy->portals = layout.portals;
    copy->rooms.reserve(layout.rooms.size());
    for (const layout::Room& room : layout.rooms) {
        layout::Room r;
        r.id = room.id;
        r.min = room.min;
        r.max = room.max;
        r.floor = room.floor;
        r.face_color.resize(room.face_color.size());
        r.face_texture.resize(room.face_texture.size());
        copy->rooms.push_back(std::move(r));
    }
    return copy;
}

// Whether a prop at rest is cut by a door: it meets the door and reaches
// behind its plane. One that only touches the door from the front is cut to
// itself and has an empty image (the part behind the door), so it stays in
// its room's geometry, drawn as before (door frames standing against their
// doors, as in layouts/four_rooms.json).
bool cut_by_a_door(const ObjectSet& set, const ObjectSolid& solid, int room) {
    for (int d : set.room_doors[static_cast<std::size_t>(room)]) {
        const math::PortalRect& rect = set.portals[static_cast<std::size_t>(d)].rect;
        if (solid_meets_door(solid, dmat4(1.0), rect) && solid_reaches_behind(solid, dmat4(1.0), rect)) return true;
    }
    return false;
}

dmat4 translation(const dvec3& v) {
    dmat4 m(1.0);
    m[3] = dvec4(v, 1.0);
    return m;
}

dmat4 pose_matrix(const math::HeadPose& pose) {
    dmat4 m(math::head_rotation(pose));
    m[3] = dvec4(pose.position, 1.0);
    return m;
}

}  // namespace

ObjectSet build_object_set(const layout::Layout& layout, const links::PortalLinks& links) {
    ObjectSet set;
    set.walk_layout = walk_layout_of(layout);
    set.walk_links = std::make_shared<const links::PortalLinks>(links);
    set.room_doors.resize(layout.rooms.size());
    set.portals.resize(layout.portals.size());
    for (std::size_t i = 0; i < layout.portals.size(); ++i) {
        const layout::Portal& p = layout.portals[i];
        ObjectDoor& door = set.portals[i];
        door.rect = p.rect;
        door.room = p.room;
        if (p.kind != layout::PortalKind::Door) continue;
        door.target = p.target;
        door.transfer = links.transfer[i];
        set.room_doors[static_cast<std::size_t>(p.room)].push_back(static_cast<int>(i));
    }
    set.hand = hand_solid(layout.hands);
    set.dynamic.resize(layout.rooms.size());
    for (std::size_t r = 0; r < layout.rooms.size(); ++r) {
        const std::vector<layout::Prop>& props = layout.rooms[r].props;
        set.dynamic[r].assign(props.size(), false);
        for (std::size_t k = 0; k < props.size(); ++k) {
            ObjectSolid solid = solid_of(props[k]);
            const layout::Motion& motion = layout::prop_motion(props[k]);
            if (motion.keys.empty() && !cut_by_a_door(set, solid, static_cast<int>(r))) continue;
            set.dynamic[r][k] = true;
            set.props.push_back(DynamicProp{static_cast<int>(r), static_cast<int>(k), layout::prop_anchor(props[k]),
                                            motion, std::move(solid)});
        }
    }
    return set;
}

std::vector<std::vector<bool>> dynamic_props(const layout::Layout& layout, const links::PortalLinks& links) {
    return build_object_set(layout, links).dynamic;
}

HandState place_hand(const ObjectSet& set, int head_room, const dvec3& head_position, const math::HeadPose& hand) {
    Walker walker(*set.walk_layout, head_room, set.walk_links);
    walker.step(math::HeadPose{head_position});
    HandState state;
    state.teleports = walker.step(hand);
    state.room = walker.room();
    state.to_cell = walker.physical_to_virtual() * pose_matrix(hand);
    return state;
}

namespace {

// The object's own-room instance, cut by the doors it meets, then one image
// per door met.
void add_instances(const ObjectSet& set, ObjectInstance own, const ObjectSolid& solid,
                   std::vector<ObjectInstance>& out) {
    std::vector<int> met;
    for (int d : set.room_doors[static_cast<std::size_t>(own.cell)])
        if (solid_meets_door(solid, own.to_cell, set.portals[static_cast<std::size_t>(d)].rect)) met.push_back(d);
    if (met.size() > static_cast<std::size_t>(kMaxCuts)) met.resize(kMaxCuts);
    for (int d : met) own.cuts[own.cut_count++] = ObjectCut{math::portal_plane(set.portals[d].rect), false, d};
    out.push_back(own);
    for (int d : met) {
        const ObjectDoor& a = set.portals[static_cast<std::size_t>(d)];
        const ObjectDoor& b = set.portals[static_cast<std::size_t>(a.target)];
        ObjectInstance image = own;
        image.cell = b.room;
        image.to_cell = a.transfer * own.to_cell;
        image.cut_count = 1;
        image.cuts = {};
        image.cuts[0] = ObjectCut{math::portal_plane(b.rect), true, a.target};
        image.image = true;
        out.push_back(image);
    }
}

}  // namespace

std::vector<ObjectInstance> place_objects(const ObjectSet& set, const math::View& view, PropWalks* walks) {
    std::optional<PropWalks> fresh;
    if (walks == nullptr || &walks->set() != &set) walks = &fresh.emplace(set);
    std::vector<ObjectInstance> out;
    for (std::size_t k = 0; k < set.props.size(); ++k) {
        const DynamicProp& p = set.props[k];
        const PropState state = walks->at(static_cast<int>(k), view.time);
        ObjectInstance own;
        own.kind = ObjectKind::Prop;
        own.listed_room = p.room;
        own.index = p.index;
        own.cell = state.room;
        own.to_cell = state.w * translation(state.offset);
        add_instances(set, own, p.solid, out);
    }
    if (!view.hands) return out;
    for (int h = 0; h < 2; ++h) {
        const HandState state =
            place_hand(set, view.room, view.head.position, (*view.hands)[static_cast<std::size_t>(h)]);
        ObjectInstance own;
        own.kind = ObjectKind::Hand;
        own.index = h;
        own.cell = state.room;
        own.to_cell = state.to_cell;
        add_instances(set, own, set.hand, out);
    }
    return out;
}

}  // namespace impossible::walk
