#include "trace/trace_scene.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <variant>

#include <glm/geometric.hpp>

#include "lights/light_bound.hpp"
#include "links/portal_links.hpp"
#include "trace/bvh.hpp"
#include "trace/prism_faces.hpp"

namespace impossible::trace {

AxisRect room_face_rect(const dvec3& room_min, const dvec3& room_max, layout::Face face) {
    AxisRect r;
    r.lo = room_min;
    r.hi = room_max;
    switch (face) {
        case layout::Face::Floor:
            r.axis = 1;
            r.coord = room_min.y;
            r.sign = 1.0;
            break;
        case layout::Face::Ceiling:
            r.axis = 1;
            r.coord = room_max.y;
            r.sign = -1.0;
            break;
        case layout::Face::NegX:
            r.axis = 0;
            r.coord = room_min.x;
            r.sign = 1.0;
            break;
        case layout::Face::PosX:
            r.axis = 0;
            r.coord = room_max.x;
            r.sign = -1.0;
            break;
        case layout::Face::NegZ:
            r.axis = 2;
            r.coord = room_min.z;
            r.sign = 1.0;
            break;
        case layout::Face::PosZ:
            r.axis = 2;
            r.coord = room_max.z;
            r.sign = -1.0;
            break;
    }
    return r;
}

bool cuts_hole(const AxisRect& face, const math::PortalRect& rect) {
    if (!(rect.normal[face.axis] * face.sign > 0.5)) return false;  // not facing into the room
    dvec3 corners[8];
    math::box_corners(rect, corners);  // the first four are the rectangle's
    const double eps = kHolePlaneTolerance;
    for (int k = 0; k < 4; ++k) {
        const dvec3& c = corners[k];
        if (std::abs(c[face.axis] - face.coord) > eps) return false;
        for (int a = 0; a < 3; ++a) {
            if (a == face.axis) continue;
            if (c[a] < face.lo[a] - eps || c[a] > face.hi[a] + eps) return false;
        }
    }
    return true;
}

namespace {

// A prop's surfaces added to a room's or an object's (SceneRoom,
// SceneObject), in the layout's coordinates as written.
Result<void> add_prop(PropSurfaces& room, const layout::Prop& prop) {
    if (const auto* box = std::get_if<layout::BoxProp>(&prop)) {
        room.boxes.push_back({box->min, box->max, box->color});
        return {};
    }
    const auto& model = std::get<layout::GltfProp>(prop);
    // The model's materials follow the room's earlier ones.
    const int first_material = static_cast<int>(room.materials.size());
    const int texture_count = static_cast<int>(model.textures.size());
    for (const assets::Material& m : model.materials) {
        if (m.texture < -1 || m.texture >= texture_count)
            return Error{"model '" + model.path + "': a material names no texture of the model"};
        PropMaterial material;
        material.alpha = m.base_color.a;
        if (m.texture >= 0) material.texture = model.textures[m.texture];
        material.double_sided = m.double_sided;
        material.mask = m.alpha_mode == assets::AlphaMode::Mask;
        material.alpha_cutoff = m.alpha_cutoff;
        room.materials.push_back(material);
    }
    const int material_count = static_cast<int>(model.materials.size());
    for (const assets::ModelTriangle& t : model.triangles) {
        if (t.material < -1 || t.material >= material_count)
            return Error{"model '" + model.path + "': a triangle names no material of the model"};
        PropTriangle placed;
        for (int k = 0; k < 3; ++k) {
            placed.position[k] = layout::place_model_point(model, t.position[k]);
            placed.normal[k] = layout::place_model_normal(model, t.normal[k]);
        }
        // With a material, its factor is the rule's (ModelTriangle::color holds the same).
        placed.color = t.material >= 0 ? dvec3(model.materials[t.material].base_color) : t.color;
        placed.vertex_color = t.vertex_color;
        placed.uv = t.uv;
        placed.material = t.material >= 0 ? first_material + t.material : -1;
        room.triangles.push_back(placed);
    }
    return {};
}

std::optional<Error> check_portals(const layout::Layout& layout) {
    const int room_count = static_cast<int>(layout.rooms.size());
    const int portal_count = static_cast<int>(layout.portals.size());
    for (const layout::Portal& p : layout.portals) {
        const bool mirror = p.kind == layout::PortalKind::Mirror;
        if (p.room < 0 || p.room >= room_count || (!mirror && (p.target < 0 || p.target >= portal_count)))
            return Error{"portal '" + p.id + "' has no valid room or target"};
    }
    // A volume's target shows only inside it: a room without portals of
    // any kind (layout-format.md, "Volume portals").
    for (const layout::Volume& v : layout.volumes) {
        const auto has_portals = [&](int room) {
            for (const layout::Portal& p : layout.portals)
                if (p.room == room) return true;
            for (const layout::Volume& w : layout.volumes)
                if (w.room == room) return true;
            return false;
        };
        if (v.room < 0 || v.room >= room_count || v.target_room < 0 || v.target_room >= room_count ||
            v.target_room == v.room || has_portals(v.target_room))
            return Error{"volume '" + v.id + "' has no valid room or target"};
    }
    return std::nullopt;
}

SceneRoom scene_room(const layout::Room& room) {
    SceneRoom r;
    if (layout::is_prism(room)) r.prism = prism_shape(room);  // its `faces` stay unused
    for (int f = 0; f < layout::kFaceCount && !layout::is_prism(room); ++f) {
        r.faces[f].rect = room_face_rect(room.min, room.max, static_cast<layout::Face>(f));
        r.faces[f].face = static_cast<layout::Face>(f);
        r.faces[f].color = room.face_color[f];
        r.faces[f].texture = room.face_texture[f];
        r.faces[f].texture_size = room.texture_size;
    }
    r.checker = room.checker;
    r.ambient = room.ambient;
    r.lights = room.lights;
    return r;
}

void build_trees(PropSurfaces& s) {
    s.bvh = build_bvh(s.triangles);
    if (s.boxes.size() > static_cast<std::size_t>(kBvhLeafSize)) s.box_bvh = build_box_bvh(s.boxes);
}

void add_portal(Scene& scene, const layout::Layout& layout, int i) {
    const layout::Portal& p = layout.portals[i];
    const bool mirror = p.kind == layout::PortalKind::Mirror;
    ScenePortal sp;
    sp.rect = p.rect;
    sp.right = math::portal_right(p.rect);
    sp.room = p.room;
    sp.target = mirror ? -1 : p.target;
    sp.kind = p.kind;
    if (p.kind != layout::PortalKind::Door) sp.tint = p.tint;
    if (p.kind == layout::PortalKind::Window) sp.reflectance = p.reflectance;
    sp.to_local = math::portal_frame_inverse(p.rect);
    if (!mirror) sp.transfer = math::transfer_matrix(p.rect, layout.portals[p.target].rect);
    if (p.kind != layout::PortalKind::Door) sp.reflection = math::reflection_matrix(p.rect);
    sp.clip_tolerance = 1e-9 * (1.0 + glm::length(p.rect.center));
    sp.plane = math::portal_plane(p.rect);
    scene.portals.push_back(sp);

    SceneRoom& room = scene.rooms[p.room];
    room.portals.push_back(i);
    // The face whose hole the rectangle fills (a rectangle lies in one
    // face's plane at most).
    RoomFace* holed = nullptr;
    if (const layout::Room& own = layout.rooms[p.room]; layout::is_prism(own)) {
        if (const int f = prism_hole_face(room.prism, p.rect); f >= 0)
            holed = &room.prism.faces[std::size_t(f)].surface;
    } else {
        for (RoomFace& face : room.faces) {
            if (cuts_hole(face.rect, p.rect)) {
                holed = &face;
                break;
            }
        }
    }
    if (holed) {
        holed->holes.push_back(i);
        scene.portals[i].in_hole = true;
    }
    if (!scene.portals[i].in_hole || p.kind == layout::PortalKind::Door) room.box_portals.push_back(i);
}

SceneVolume scene_volume(const layout::Volume& v) {
    SceneVolume sv;
    sv.center = v.rect.center;
    sv.right = math::portal_right(v.rect);
    sv.up = v.rect.up;
    sv.normal = v.rect.normal;
    sv.half = 0.5 * dvec3(v.rect.width, v.rect.height, v.rect.depth);
    sv.tolerance = 1e-9 * (1.0 + glm::length(v.rect.center));
    sv.target = v.target_room;
    sv.tint = v.tint;
    return sv;
}

// The dynamic props' surfaces (Scene::props, in ObjectSet::props' order)
// and the hand's: a box of HandShape::box centred on the origin, or the
// model's triangles scaled (its position and yaw are 0).
Result<void> add_objects(Scene& scene, const layout::Layout& layout) {
    for (const walk::DynamicProp& d : scene.objects.props) {
        SceneObject object;
        if (Result<void> added = add_prop(object, layout.rooms[d.room].props[d.index]); !added) return added;
        build_trees(object);
        scene.prop_object[d.room][d.index] = static_cast<int>(scene.props.size());
        scene.props.push_back(std::move(object));
    }
    const layout::HandShape& hand = layout.hands;
    if (hand.model) {
        if (Result<void> added = add_prop(scene.hand, layout::Prop(*hand.model)); !added) return added;
    } else {
        scene.hand.boxes.push_back({-0.5 * hand.box, 0.5 * hand.box, hand.color});
    }
    build_trees(scene.hand);
    return {};
}

}  // namespace

Result<Scene> prepare_scene(const layout::Layout& layout) { return prepare_scene(layout, links::link_portals(layout)); }

Result<Scene> prepare_scene(const layout::Layout& layout, const links::PortalLinks& links) {
    if (const std::optional<Error> error = check_portals(layout)) return *error;
    Scene scene;
    scene.lit = layout.lighting == layout::Lighting::Lights;
    scene.exposure = layout.exposure;
    // The rasteriser's bound (build_scene.cpp): the same depth and lights.
    const lights::LightBound bound = lights::light_bound(layout, links);
    scene.max_light_depth = bound.depth;
    scene.light_depth = std::min(layout.light_depth, scene.max_light_depth);
    scene.objects = walk::build_object_set(layout, links);
    for (std::size_t r = 0; r < layout.rooms.size(); ++r) {
        const layout::Room& room = layout.rooms[r];
        SceneRoom sr = scene_room(room);
        sr.lights = lights::lit_lights(layout, bound, static_cast<int>(r));
        // A dynamic prop is no part of its room: it is placed each frame.
        for (std::size_t k = 0; k < room.props.size(); ++k) {
            if (r < scene.objects.dynamic.size() && k < scene.objects.dynamic[r].size() && scene.objects.dynamic[r][k])
                continue;
            if (Result<void> added = add_prop(sr, room.props[k]); !added) return added;
        }
        build_trees(sr);
        scene.rooms.push_back(std::move(sr));
        scene.prop_object.emplace_back(room.props.size(), -1);
    }
    for (int i = 0; i < static_cast<int>(layout.portals.size()); ++i) add_portal(scene, layout, i);
    for (const layout::Volume& v : layout.volumes) scene.rooms[v.room].volumes.push_back(scene_volume(v));
    if (Result<void> added = add_objects(scene, layout); !added) return added;
    if (!scene.rooms.empty()) scene.rest = place_frame_objects(scene, math::View{});
    return scene;
}

}  // namespace impossible::trace
