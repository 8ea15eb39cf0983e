// A door facing out of its room (readers.hpp, warn_doors_facing_out): it
// lies in a face's plane, inside the face, but its normal points out of the
// room, so the hole rule (hole_rule.cpp) lets it stand free, hidden in the
// face, where nobody sees or walks through it.
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

#include "base/format.hpp"
#include "base/user_text.hpp"
#include "layout/limits.hpp"
#include "layout/readers.hpp"
#include "layout/room_shape.hpp"
#include "math/polygon.hpp"

namespace impossible::layout::detail {
namespace {

std::array<glm::dvec3, 4> rect_corners(const math::PortalRect& p) {
    const glm::dvec3 right = glm::cross(p.up, p.normal) * (p.width / 2);
    const glm::dvec3 up = p.up * (p.height / 2);
    return {p.center - right - up, p.center + right - up, p.center + right + up, p.center - right + up};
}

// "[-1, 0, 0]": the normal turned around, to six decimals.
std::string flipped(const glm::dvec3& n) {
    std::string out = "[";
    for (int i = 0; i < 3; ++i) {
        const double v = std::round(-n[i] * 1e6) / 1e6 + 0.0;
        out += (i ? ", " : "") + format_number(v);
    }
    return out + "]";
}

// The face of `room` the door lies in, facing out of the room, or -1.
int face_facing_out(const Room& room, const math::PortalRect& rect) {
    const double eps = limits::kHolePlaneTolerance;
    const std::array<glm::dvec3, 4> c = rect_corners(rect);
    for (int face = 0; face < face_count(room); ++face) {
        const FaceFrame f = face_frame(room, face);
        if (!(glm::dot(rect.normal, f.normal) < -0.5)) continue;
        bool inside = true;
        for (const glm::dvec3& v : c) inside = inside && std::abs(glm::dot(v - f.origin, f.normal)) <= eps;
        for (std::size_t k = 0; k < 4 && inside; ++k)
            inside = math::segment_inside(f.outline, to_face(f, c[k]), to_face(f, c[(k + 1) % 4]), eps);
        if (inside) return face;
    }
    return -1;
}

}  // namespace

void warn_doors_facing_out(Checker& check, const std::vector<PortalDraft>& portals,
                           const std::vector<RoomDraft>& rooms) {
    for (const PortalDraft& draft : portals) {
        const Portal& p = draft.portal;
        if (!draft.rect_ok || !draft.kind_ok || draft.volume || p.kind != PortalKind::Door || p.room < 0 ||
            p.hole_face >= 0)
            continue;
        const RoomDraft& room = rooms[static_cast<std::size_t>(p.room)];
        if (!room.shape_ok) continue;
        const int face = face_facing_out(room.room, p.rect);
        if (face < 0) continue;
        check.loud_warning(draft.path / "normal",
                           "door " + quote(p.id) + " lies in the " + face_name(room.room, face) + " face of room " +
                               quote(room.room.id) +
                               " but its normal points out of the room, so it makes no hole: it stands free, hidden "
                               "in the face, and nobody can see or walk through it; flip the normal to " +
                               flipped(p.rect.normal));
    }
}

}  // namespace impossible::layout::detail
