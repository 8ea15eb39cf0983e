#include "trace/trace_scene.hpp"

#include <cmath>
#include <string>
#include <variant>

#include <glm/geometric.hpp>

#include "trace/bvh.hpp"

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

Result<void> add_prop(SceneRoom& room, const layout::Prop& prop) {
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

}  // namespace

Result<Scene> prepare_scene(const layout::Layout& layout) {
    Scene scene;
    const int room_count = static_cast<int>(layout.rooms.size());
    const int portal_count = static_cast<int>(layout.portals.size());
    for (const layout::Room& room : layout.rooms) {
        SceneRoom r;
        for (int f = 0; f < layout::kFaceCount; ++f) {
            r.faces[f].rect = room_face_rect(room.min, room.max, static_cast<layout::Face>(f));
            r.faces[f].face = static_cast<layout::Face>(f);
            r.faces[f].color = room.face_color[f];
            r.faces[f].texture = room.face_texture[f];
            r.faces[f].texture_size = room.texture_size;
        }
        for (const layout::Prop& prop : room.props)
            if (Result<void> added = add_prop(r, prop); !added) return added;
        r.bvh = build_bvh(r.triangles);
        if (r.boxes.size() > static_cast<std::size_t>(kBvhLeafSize)) r.box_bvh = build_box_bvh(r.boxes);
        r.checker = room.checker;
        scene.rooms.push_back(std::move(r));
    }
    for (int i = 0; i < portal_count; ++i) {
        const layout::Portal& p = layout.portals[i];
        const bool mirror = p.kind == layout::PortalKind::Mirror;
        if (p.room < 0 || p.room >= room_count || (!mirror && (p.target < 0 || p.target >= portal_count)))
            return Error{"portal '" + p.id + "' has no valid room or target"};
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
        for (RoomFace& face : room.faces) {
            if (cuts_hole(face.rect, p.rect)) {
                face.holes.push_back(i);
                scene.portals[i].in_hole = true;
                break;  // a rectangle lies in one face's plane at most
            }
        }
        if (!scene.portals[i].in_hole || p.kind == layout::PortalKind::Door) room.box_portals.push_back(i);
    }
    return scene;
}

}  // namespace impossible::trace
