// A frame's dynamic objects for the tracer (trace_scene.hpp, FrameObjects),
// and the filter that cuts them, hides a room inside its volumes and shows a
// volume's target room only inside it (intersect.hpp, RayFilter).
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "trace/intersect.hpp"
#include "trace/trace_scene.hpp"

namespace impossible::trace {

bool SceneVolume::contains(const dvec3& p) const {
    const dvec3 v = p - center;
    return std::abs(glm::dot(v, right)) <= half.x + tolerance && std::abs(glm::dot(v, up)) <= half.y + tolerance &&
           std::abs(glm::dot(v, normal)) <= half.z + tolerance;
}

bool filtered_keeps(const ClipPlane& clip, const dvec3& point) {
    const RayFilter& f = *clip.filter;
    const dvec3 p = f.placed ? dvec3(f.placed->to_cell * dvec4(point, 1.0)) : point;
    if (clip.active && !(plane_distance(clip.plane, p) > clip.tolerance)) return false;
    if (f.placed) {
        for (int k = 0; k < f.placed->cut_count; ++k) {
            const ObjectCutPlane& cut = f.placed->cuts[k];
            const double d = plane_distance(cut.plane, p);
            if (cut.strict ? !(d > cut.tolerance) : !(d >= -cut.tolerance)) return false;
        }
    }
    for (const SceneVolume& v : f.outside)
        if (v.contains(p)) return false;
    return !f.inside || f.inside->contains(p);
}

namespace {

// The inverse of a rigid matrix (a rotation and a move): Rᵀ and -Rᵀ·t,
// without a general inverse's rounding.
dmat4 rigid_inverse(const dmat4& m) {
    const dmat3 rt = glm::transpose(dmat3(m));
    dmat4 inverse(rt);
    inverse[3] = dvec4(-(rt * dvec3(m[3])), 1.0);
    return inverse;
}

// The scene's object an instance draws: an index into Scene::props, -1 for
// the hand, -2 for none (an instance of a prop the scene has as static).
int object_of(const Scene& scene, const walk::ObjectInstance& instance) {
    if (instance.kind == walk::ObjectKind::Hand) return -1;
    const int room = instance.listed_room, index = instance.index;
    if (room < 0 || room >= static_cast<int>(scene.prop_object.size())) return -2;
    const std::vector<int>& props = scene.prop_object[room];
    if (index < 0 || index >= static_cast<int>(props.size()) || props[index] < 0) return -2;
    return props[index];
}

PlacedObject place(const Scene& scene, const walk::ObjectInstance& instance) {
    PlacedObject p;
    p.prop = object_of(scene, instance);
    p.cell = instance.cell;
    p.to_cell = instance.to_cell;
    p.from_cell = rigid_inverse(instance.to_cell);
    p.rotation = dmat3(instance.to_cell);
    p.cut_count = std::clamp(instance.cut_count, 0, walk::kMaxCuts);
    for (int k = 0; k < p.cut_count; ++k) {
        const walk::ObjectCut& cut = instance.cuts[k];
        p.cuts[k] = {cut.plane, cut.strict, scene.portals[cut.door].clip_tolerance};
    }
    return p;
}

}  // namespace

FrameObjects place_frame_objects(const Scene& scene, const math::View& view) {
    FrameObjects frame;
    const int rooms = static_cast<int>(scene.rooms.size());
    // Hands are walked from the head's room: without a valid one, none.
    const bool hands = view.hands && view.room >= 0 && view.room < rooms;
    if (scene.objects.props.empty() && !hands) return frame;
    math::View placed_view = view;
    if (!hands) placed_view.hands.reset();
    const std::vector<walk::ObjectInstance> instances = walk::place_objects(scene.objects, placed_view);
    std::vector<int> count(rooms + 1, 0);
    auto drawn = [&](const walk::ObjectInstance& instance) {
        return instance.cell >= 0 && instance.cell < rooms && object_of(scene, instance) >= -1;
    };
    for (const walk::ObjectInstance& instance : instances)
        if (drawn(instance)) ++count[instance.cell + 1];
    if (std::all_of(count.begin(), count.end(), [](int c) { return c == 0; })) return frame;
    frame.first.assign(rooms + 1, 0);
    for (int r = 0; r < rooms; ++r) frame.first[r + 1] = frame.first[r] + count[r + 1];
    // Grouped per cell, each cell's in place_objects' order (a stable sort).
    frame.placed.resize(frame.first[rooms]);
    std::vector<int> next(frame.first.begin(), frame.first.end() - 1);
    for (const walk::ObjectInstance& instance : instances)
        if (drawn(instance)) frame.placed[next[instance.cell]++] = place(scene, instance);
    return frame;
}

}  // namespace impossible::trace
