#include "render/objects/object_culling.hpp"

#include <algorithm>
#include <array>
#include <cassert>

#include "render/objects/box_faces.hpp"
#include "scene/mesh_writer.hpp"

namespace impossible::render {

namespace {

// Up to five planes (a, b, c, d): a point p is inside when a·x + b·y + c·z + d >= 0.
struct EyePlanes {
    std::array<math::dvec4, 5> planes;
    int count = 0;
};

// The eye's frustum through its rectangle: clip-space x >= x0·w and the
// like, as planes in the cell's coordinates (rows of the view-projection
// matrix); they pass through the eye, so together they also keep w >= 0.
EyePlanes eye_planes(const EyeView& ev, const NdcRect& r) {
    const math::dmat4& m = ev.view_proj;
    const auto row = [&](int i) { return math::dvec4(m[0][i], m[1][i], m[2][i], m[3][i]); };
    const math::dvec4 x = row(0), y = row(1), w = row(3);
    EyePlanes out;
    out.planes[0] = x - r.x0 * w;
    out.planes[1] = r.x1 * w - x;
    out.planes[2] = y - r.y0 * w;
    out.planes[3] = r.y1 * w - y;
    out.count = 4;
    if (ev.clip_plane != math::dvec4(0, 0, 0, 1)) out.planes[static_cast<std::size_t>(out.count++)] = ev.clip_plane;
    return out;
}

// Whether a box lies wholly on the outer side of some plane.
bool outside(const EyePlanes& e, const glm::dvec3& lo, const glm::dvec3& hi) {
    for (int i = 0; i < e.count; ++i) {
        const math::dvec4& p = e.planes[static_cast<std::size_t>(i)];
        const glm::dvec3 far(p.x >= 0 ? hi.x : lo.x, p.y >= 0 ? hi.y : lo.y, p.z >= 0 ? hi.z : lo.z);
        if (p.x * far.x + p.y * far.y + p.z * far.z + p.w < 0.0) return true;
    }
    return false;
}

// Whether the segment from `eye` to `p` enters the box at least a
// millimetre before `p`, from outside.
bool behind_box(const math::dvec3& eye, const math::dvec3& p, const glm::dvec3& lo, const glm::dvec3& hi) {
    const math::dvec3 d = p - eye;
    double enter = 0.0, exit = 1.0;
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0.0) {
            if (eye[a] <= lo[a] || eye[a] >= hi[a]) return false;
            continue;
        }
        double t0 = (lo[a] - eye[a]) / d[a], t1 = (hi[a] - eye[a]) / d[a];
        if (t0 > t1) std::swap(t0, t1);
        enter = std::max(enter, t0);
        exit = std::min(exit, t1);
    }
    const double length = glm::length(d);
    // enter > 0: the eye is outside (a box seen from inside hides nothing).
    return enter > 0.0 && enter <= exit && (1.0 - enter) * length > 1e-3;
}

}  // namespace

bool hidden_by_occluder(const scene::CellObjects& cell, const EyeView& eye, const math::PortalRect& portal) {
    if (cell.occluders.empty()) return false;
    math::dvec3 corners[8];
    math::box_corners(portal, corners);
    const bool clipped = eye.clip_plane != math::dvec4(0, 0, 0, 1);
    for (const auto& [lo, hi] : cell.occluders) {
        if (clipped) {
            bool in_front = true;
            for (int k = 0; k < 8 && in_front; ++k) {
                const math::dvec3 c((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z);
                in_front = glm::dot(math::dvec3(eye.clip_plane), c) + eye.clip_plane.w > 0.0;
            }
            if (!in_front) continue;
        }
        bool all = true;
        for (int k = 0; k < 8 && all; ++k) all = behind_box(eye.eye.position, corners[k], lo, hi);
        if (all) return true;
    }
    return false;
}

namespace {

// Fills scratch.visible with the objects of the cell's tree whose bounds an
// active eye may see (see visible_batches), left subtrees first.
void collect_visible(const scene::CellObjects& cell, const LevelView& view, int eye_width, int eye_height,
                     double margin_px, CullScratch& scratch) {
    std::array<EyePlanes, 2> eyes;
    int eye_count = 0;
    for (const EyeView& ev : view.eyes) {
        if (!ev.active || ev.rect.empty()) continue;
        eyes[static_cast<std::size_t>(eye_count++)] =
            eye_planes(ev, widened(ev.rect, margin_px, eye_width, eye_height));
    }
    const auto hidden = [&](const glm::dvec3& lo, const glm::dvec3& hi) {
        for (int e = 0; e < eye_count; ++e)
            if (!outside(eyes[static_cast<std::size_t>(e)], lo, hi)) return false;
        return true;
    };

    scratch.visible.clear();
    scratch.stack.clear();
    scratch.stack.push_back(0);
    while (!scratch.stack.empty()) {
        const scene::CullNode& node = cell.nodes[static_cast<std::size_t>(scratch.stack.back())];
        const int index = scratch.stack.back();
        scratch.stack.pop_back();
        if (hidden(node.lo, node.hi)) continue;
        if (node.count == 0) {
            scratch.stack.push_back(node.first);
            scratch.stack.push_back(index + 1);
            continue;
        }
        for (int i = node.first; i < node.first + node.count; ++i) {
            const int o = cell.order[static_cast<std::size_t>(i)];
            const scene::CellObject& object = cell.objects[static_cast<std::size_t>(o)];
            if (node.count == 1 || !hidden(object.lo, object.hi)) scratch.visible.push_back(o);
        }
    }
}

}  // namespace

void visible_objects(const scene::CellObjects& cell, const LevelView& view, int eye_width, int eye_height,
                     double margin_px, CullScratch& scratch, std::vector<int>& out) {
    out.clear();
    if (cell.nodes.empty()) return;
    collect_visible(cell, view, eye_width, eye_height, margin_px, scratch);
    out.assign(scratch.visible.begin(), scratch.visible.end());
    std::sort(out.begin(), out.end());
}

void visible_batches(const scene::CellObjects& cell, const LevelView& view, int eye_width, int eye_height,
                     double margin_px, CullScratch& scratch, std::vector<scene::DrawBatch>& out) {
    if (cell.nodes.empty()) {
        out.assign(cell.surfaces.begin(), cell.surfaces.end());
        return;
    }
    out.clear();
    collect_visible(cell, view, eye_width, eye_height, margin_px, scratch);
    // Left subtrees first, and finish_cell numbers the objects in leaf order:
    // the visible ones come out in the order their indices are stored.
    assert(std::is_sorted(scratch.visible.begin(), scratch.visible.end()));
    for (const int o : scratch.visible) {
        const scene::CellObject& object = cell.objects[static_cast<std::size_t>(o)];
        for (std::uint32_t b = object.first_batch; b < object.first_batch + object.batch_count; ++b)
            scene::add_batch(out, cell.batches[b]);
    }
    for (const scene::DrawBatch& b : cell.surfaces) scene::add_batch(out, b);
}

void visible_draws(const scene::CellObjects& cell, const LevelView& view, int eye_width, int eye_height,
                   double margin_px, const BoxFaceView& faces, CullScratch& scratch,
                   std::vector<std::uint32_t>& face_indices, std::vector<VisibleDraw>& out) {
    out.clear();
    face_indices.clear();
    const auto add = [&](const scene::DrawBatch& b) {
        if (!out.empty() && !out.back().faces && out.back().batch.same_state(b) &&
            out.back().batch.range.first + out.back().batch.range.count == b.range.first) {
            out.back().batch.range.count += b.range.count;
            return;
        }
        if (b.range.count > 0) out.push_back({b, false});
    };
    if (!cell.nodes.empty()) {
        collect_visible(cell, view, eye_width, eye_height, margin_px, scratch);
        assert(std::is_sorted(scratch.visible.begin(), scratch.visible.end()));
    } else {
        scratch.visible.clear();
    }
    for (const int o : scratch.visible) {
        const scene::CellObject& object = cell.objects[static_cast<std::size_t>(o)];
        if (object.box_vertex < 0) {
            for (std::uint32_t b = object.first_batch; b < object.first_batch + object.batch_count; ++b)
                add(cell.batches[b]);
            continue;
        }
        const auto first = static_cast<std::uint32_t>(face_indices.size());
        append_box_faces(static_cast<std::uint32_t>(object.box_vertex),
                         box_front_faces(object.lo, object.hi, view, faces) &
                             ~faces_in_clip_planes(object.box_min, object.box_max, view),
                         face_indices);
        const auto count = static_cast<std::uint32_t>(face_indices.size()) - first;
        if (count == 0) continue;
        if (!out.empty() && out.back().faces)
            out.back().batch.range.count += count;
        else
            out.push_back({scene::DrawBatch{{first, count}}, true});
    }
    for (const scene::DrawBatch& b : cell.surfaces) add(b);
}

}  // namespace impossible::render
