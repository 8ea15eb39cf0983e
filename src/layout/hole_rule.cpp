// The hole rule (layout-format.md, "The portal box"): a portal whose
// rectangle lies in the plane of a face of its own room (all four corners
// within 1e-4 of it, normal into the room) cuts a hole in that face if it is
// wholly inside the face; wholly outside, it stands free; partly inside is an
// error. Two holes in one face that overlap are an error too (the face
// would have no defined shape between them). Mirrors and windows must make
// a hole ("Mirrors and windows"): standing free, they are an error.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

#include <glm/geometric.hpp>

#include "base/file_io.hpp"
#include "base/format.hpp"
#include "base/user_text.hpp"
#include "layout/limits.hpp"
#include "layout/readers.hpp"
#include "layout/room_shape.hpp"
#include "math/polygon.hpp"

namespace impossible::layout::detail {

namespace {

using Quad = std::array<glm::dvec2, 4>;

// A face of a room: the plane coordinate on `axis`, the inward direction
// along it, and the face rectangle over axes (a, b).
struct FaceAxes {
    int axis = 0;
    double coord = 0.0;
    double inward = 1.0;
    int a = 0;
    int b = 0;
    glm::dvec2 lo{0.0};
    glm::dvec2 hi{0.0};
};

FaceAxes face_axes(const Room& room, Face face) {
    FaceAxes f;
    switch (face) {
        case Face::Floor: f = {1, room.min.y, 1.0, 0, 2}; break;
        case Face::Ceiling: f = {1, room.max.y, -1.0, 0, 2}; break;
        case Face::NegX: f = {0, room.min.x, 1.0, 2, 1}; break;
        case Face::PosX: f = {0, room.max.x, -1.0, 2, 1}; break;
        case Face::NegZ: f = {2, room.min.z, 1.0, 0, 1}; break;
        case Face::PosZ: f = {2, room.max.z, -1.0, 0, 1}; break;
    }
    f.lo = {room.min[f.a], room.min[f.b]};
    f.hi = {room.max[f.a], room.max[f.b]};
    return f;
}

std::array<glm::dvec3, 4> corners(const math::PortalRect& p) {
    const glm::dvec3 right = glm::cross(p.up, p.normal) * (p.width / 2);
    const glm::dvec3 up = p.up * (p.height / 2);
    return {p.center - right - up, p.center + right - up, p.center + right + up, p.center - right + up};
}

// The least overlap of the projections of two convex quads over their edge
// normals: > 0 where their interiors overlap, <= 0 where they are apart or
// touch (the separating axis theorem).
double overlap(const Quad& p, const Quad& q) {
    double least = std::numeric_limits<double>::infinity();
    for (const Quad* shape : {&p, &q}) {
        for (int e = 0; e < 2; ++e) {
            const glm::dvec2 edge = (*shape)[static_cast<std::size_t>(e + 1)] - (*shape)[static_cast<std::size_t>(e)];
            const double length = glm::length(edge);
            if (!(length > 0.0)) continue;
            const glm::dvec2 axis = edge / length;
            const auto project = [&](const Quad& s) {
                double lo = std::numeric_limits<double>::infinity();
                double hi = -lo;
                for (const glm::dvec2& v : s) {
                    lo = std::min(lo, glm::dot(v, axis));
                    hi = std::max(hi, glm::dot(v, axis));
                }
                return std::pair{lo, hi};
            };
            const auto [p_lo, p_hi] = project(p);
            const auto [q_lo, q_hi] = project(q);
            least = std::min(least, std::min(p_hi, q_hi) - std::max(p_lo, q_lo));
        }
    }
    return least;
}

// Why a mirror or window is in no face: its corners are `away` m from the
// face its normal looks away from (`facing`), or its normal is tilted.
std::string away_reason(double away, const std::string& face_text, bool facing) {
    if (!facing) {
        return "its normal is tilted away from every face; make it perpendicular to the face it belongs in, "
               "pointing into the room";
    }
    const double micrometres = std::round(away * 1e6) / 1e6;  // no 0.30000000000000004
    return "a corner is " + format_number(micrometres) + " m from " + face_text +
           ", the face its normal looks away from; move it into that face";
}

void refuse_free_glass(Checker& check, const PortalDraft& draft, const Room& room, double eps, const std::string& why) {
    check.error(draft.path / "center",
                std::string("a ") + kind_name(draft.portal.kind) + " must lie in a face of its own room " +
                    quote(room.id) + " (within " + format_number(eps) +
                    " m of the face's plane, inside the face), but this one stands free: " + why);
}

// A mirror or window that stands free (layout-format.md, "Mirrors and
// windows": it must lie in a face of its own room). The message says which
// face it is nearest and what to change.
void report_free_standing(Checker& check, const PortalDraft& draft, const Room& room,
                          const std::array<glm::dvec3, 4>& c) {
    const double eps = limits::kHolePlaneTolerance;
    const math::PortalRect& rect = draft.portal.rect;
    static const char* const axes[] = {"x", "y", "z"};
    const auto name = [&](int face) {
        const FaceAxes f = face_axes(room, static_cast<Face>(face));
        return std::string("the ") + kFaceNames[static_cast<std::size_t>(face)] + " face (" + axes[f.axis] + " = " +
               format_number(f.coord) + ")";
    };
    const auto farthest_corner = [&](const FaceAxes& f) {
        double away = 0.0;
        for (const glm::dvec3& v : c) away = std::max(away, std::abs(v[f.axis] - f.coord));
        return away;
    };
    std::string why;
    for (int face = 0; face < kFaceCount && why.empty(); ++face) {
        const FaceAxes f = face_axes(room, static_cast<Face>(face));
        if (farthest_corner(f) > eps) continue;
        // In the plane: either the normal points out of the room, or the
        // rectangle lies beside the face (partly inside is reported apart).
        why = rect.normal[f.axis] * f.inward > 0.5
                  ? "it lies in the plane of " + name(face) + " but outside that face; move it inside the face"
                  : "it lies in the plane of " + name(face) +
                        " but its normal points out of the room; turn the normal around";
    }
    if (why.empty()) {
        // The face the normal looks away from, where it would belong.
        int best = 0;
        for (int face = 1; face < kFaceCount; ++face) {
            const FaceAxes f = face_axes(room, static_cast<Face>(face));
            const FaceAxes b = face_axes(room, static_cast<Face>(best));
            if (rect.normal[f.axis] * f.inward > rect.normal[b.axis] * b.inward) best = face;
        }
        const FaceAxes f = face_axes(room, static_cast<Face>(best));
        why = away_reason(farthest_corner(f), name(best), rect.normal[f.axis] * f.inward > 0.5);
    }
    refuse_free_glass(check, draft, room, eps, why);
}

struct Hole {
    std::size_t portal = 0;
    Quad quad{};
    double min_a = 0.0;
    double max_a = 0.0;
};

using FaceHoles = std::map<std::pair<int, int>, std::vector<Hole>>;  // (room, face) → holes

// A portal in the plane of `face` that is only partly inside it.
void report_partly_inside(Checker& check, const PortalDraft& draft, int face, const Room& room) {
    // A mirror or window has only one way out: into the face.
    const bool boxless = draft.kind_ok && draft.portal.kind != PortalKind::Door;
    const std::string rule =
        boxless ? std::string("a ") + kind_name(draft.portal.kind) +
                      " must lie wholly inside a face of its room, making a hole; move it inside"
                : "a portal in the plane of a face must lie wholly inside it, making a hole, or wholly "
                  "outside";
    check.error(draft.path / "center", "the rectangle lies in the plane of the " + face_name(room, face) +
                                           " face of room " + quote(room.id) +
                                           " but is only partly inside that face (" + rule + ")");
}

// Portal `i`'s hole in a box room, if it makes one: sets its hole_face and
// adds it to `holes`. A portal partly inside a face, or a mirror or window
// standing free, is an error.
void find_box_hole(Checker& check, std::size_t i, PortalDraft& draft, const RoomDraft& room, FaceHoles& holes) {
    const double eps = limits::kHolePlaneTolerance;
    const int room_index = draft.portal.room;
    const math::PortalRect& rect = draft.portal.rect;
    const std::array<glm::dvec3, 4> c = corners(rect);
    bool partly = false;
    for (int face = 0; face < kFaceCount; ++face) {
        const FaceAxes f = face_axes(room.room, static_cast<Face>(face));
        const bool in_plane =
            std::all_of(c.begin(), c.end(), [&](const glm::dvec3& v) { return std::abs(v[f.axis] - f.coord) <= eps; });
        if (!in_plane || !(rect.normal[f.axis] * f.inward > 0.5)) continue;
        Hole hole;
        hole.portal = i;
        for (std::size_t k = 0; k < 4; ++k) hole.quad[k] = {c[k][f.a], c[k][f.b]};
        const bool inside = std::all_of(hole.quad.begin(), hole.quad.end(), [&](const glm::dvec2& v) {
            return v.x >= f.lo.x - eps && v.x <= f.hi.x + eps && v.y >= f.lo.y - eps && v.y <= f.hi.y + eps;
        });
        const Quad face_quad = {f.lo, glm::dvec2(f.hi.x, f.lo.y), f.hi, glm::dvec2(f.lo.x, f.hi.y)};
        if (inside) {
            draft.portal.hole_face = face;
            hole.min_a = std::min({hole.quad[0].x, hole.quad[1].x, hole.quad[2].x, hole.quad[3].x});
            hole.max_a = std::max({hole.quad[0].x, hole.quad[1].x, hole.quad[2].x, hole.quad[3].x});
            holes[{room_index, face}].push_back(hole);
        } else if (overlap(hole.quad, face_quad) > eps) {
            partly = true;
            report_partly_inside(check, draft, face, room.room);
        }
        break;
    }
    const bool boxless = draft.kind_ok && draft.portal.kind != PortalKind::Door;
    if (boxless && draft.portal.hole_face < 0 && !partly) report_free_standing(check, draft, room.room, c);
}

// The faces of a prism room, in face order.
std::vector<FaceFrame> face_frames(const Room& room) {
    std::vector<FaceFrame> frames;
    for (int f = 0; f < face_count(room); ++f) frames.push_back(face_frame(room, f));
    return frames;
}

// "the floor (y = 0)", "wall3 (from [0, 0] to [4, 0])".
std::string prism_face_text(const Room& room, int face) {
    if (face < 2)
        return std::string("the ") +
               (face == 0 ? "floor (y = " + format_number(room.min.y) : "ceiling (y = " + format_number(room.max.y)) +
               ")";
    const Wall w = wall(room, face - 2);
    return face_name(room, face) + " (from [" + format_number(w.a.x) + ", " + format_number(w.a.y) + "] to [" +
           format_number(w.b.x) + ", " + format_number(w.b.y) + "])";
}

// A mirror or window that stands free in a prism room: which face it is
// nearest and what to change (as report_free_standing for a box).
void report_free_standing_prism(Checker& check, const PortalDraft& draft, const Room& room,
                                const std::vector<FaceFrame>& frames, const std::array<glm::dvec3, 4>& c) {
    const double eps = limits::kHolePlaneTolerance;
    const glm::dvec3 n = draft.portal.rect.normal;
    const auto farthest_corner = [&](const FaceFrame& f) {
        double away = 0.0;
        for (const glm::dvec3& v : c) away = std::max(away, std::abs(glm::dot(v - f.origin, f.normal)));
        return away;
    };
    // In a face's plane facing into the room but beside the face; else in
    // a face's plane, over the face, facing out of the room.
    std::string why;
    std::size_t best = 0;
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const bool in_plane = farthest_corner(frames[f]) <= eps;
        if (why.empty() && in_plane && glm::dot(n, frames[f].normal) > 0.5) {
            why = "it lies in the plane of " + prism_face_text(room, static_cast<int>(f)) +
                  " but outside that face; move it inside the face";
        }
        if (glm::dot(n, frames[f].normal) > glm::dot(n, frames[best].normal)) best = f;
    }
    for (std::size_t f = 0; f < frames.size() && why.empty(); ++f) {
        if (farthest_corner(frames[f]) <= eps &&
            math::contains(frames[f].outline, to_face(frames[f], draft.portal.rect.center), eps)) {
            why = "it lies in the plane of " + prism_face_text(room, static_cast<int>(f)) +
                  " but its normal points out of the room; turn the normal around";
        }
    }
    if (why.empty()) {
        why = away_reason(farthest_corner(frames[best]), prism_face_text(room, static_cast<int>(best)),
                          glm::dot(n, frames[best].normal) > 0.5);
    }
    refuse_free_glass(check, draft, room, eps, why);
}

// Whether the rectangle (in a face's (s, t)) reaches into the face by more
// than the 1e-4 sliver: for a wall, the separating-axis overlap of the two
// rectangles (as for a box); for a floor or ceiling polygon, an area inside
// it larger than a 1e-4 m strip along the rectangle's longer side.
bool reaches_into(const Quad& quad, const FaceFrame& frame, int face) {
    const double eps = limits::kHolePlaneTolerance;
    if (face >= 2) {
        const math::Polygon2& o = frame.outline;
        return overlap(quad, Quad{o[0], o[1], o[2], o[3]}) > eps;
    }
    const double side = std::max(glm::distance(quad[0], quad[1]), glm::distance(quad[1], quad[2]));
    return math::intersection_area(frame.outline, {quad.begin(), quad.end()}) > eps * side;
}

// Portal `i`'s hole in a prism room (layout-format.md, "Rooms of any shape"):
// the first face in whose plane it lies, normal into the room, and inside
// which it lies (each edge inside the face's outline within 1e-4 m). One
// wholly outside a face in its plane goes on to the next face (collinear
// walls share a plane); one partly inside is an error.
void find_prism_hole(Checker& check, std::size_t i, PortalDraft& draft, const Room& room,
                     const std::vector<FaceFrame>& frames, FaceHoles& holes) {
    const double eps = limits::kHolePlaneTolerance;
    const math::PortalRect& rect = draft.portal.rect;
    const std::array<glm::dvec3, 4> c = corners(rect);
    bool partly = false;
    for (std::size_t face = 0; face < frames.size() && !partly && draft.portal.hole_face < 0; ++face) {
        const FaceFrame& f = frames[face];
        const bool in_plane = std::all_of(
            c.begin(), c.end(), [&](const glm::dvec3& v) { return std::abs(glm::dot(v - f.origin, f.normal)) <= eps; });
        if (!in_plane || !(glm::dot(rect.normal, f.normal) > 0.5)) continue;
        Hole hole;
        hole.portal = i;
        for (std::size_t k = 0; k < 4; ++k) hole.quad[k] = to_face(f, c[k]);
        bool inside = true;
        for (std::size_t k = 0; k < 4 && inside; ++k) {
            inside = math::segment_inside(f.outline, hole.quad[k], hole.quad[(k + 1) % 4], eps);
        }
        if (inside) {
            draft.portal.hole_face = static_cast<int>(face);
            hole.min_a = std::min({hole.quad[0].x, hole.quad[1].x, hole.quad[2].x, hole.quad[3].x});
            hole.max_a = std::max({hole.quad[0].x, hole.quad[1].x, hole.quad[2].x, hole.quad[3].x});
            holes[{draft.portal.room, static_cast<int>(face)}].push_back(hole);
        } else if (reaches_into(hole.quad, f, static_cast<int>(face))) {
            partly = true;
            report_partly_inside(check, draft, static_cast<int>(face), room);
        }
    }
    const bool boxless = draft.kind_ok && draft.portal.kind != PortalKind::Door;
    if (boxless && draft.portal.hole_face < 0 && !partly) report_free_standing_prism(check, draft, room, frames, c);
}

// Overlapping holes in one face: sweep along the face's first axis.
// Each portal is reported once.
void report_overlapping_holes(Checker& check, const std::vector<PortalDraft>& portals,
                              const std::vector<RoomDraft>& rooms, FaceHoles& holes) {
    const double eps = limits::kHolePlaneTolerance;
    std::vector<bool> reported(portals.size(), false);
    for (auto& [key, list] : holes) {
        std::sort(list.begin(), list.end(), [](const Hole& x, const Hole& y) { return x.min_a < y.min_a; });
        for (std::size_t i = 0; i < list.size(); ++i) {
            for (std::size_t j = i + 1; j < list.size() && list[j].min_a < list[i].max_a - eps; ++j) {
                const std::size_t first = std::min(list[i].portal, list[j].portal);
                const std::size_t later = std::max(list[i].portal, list[j].portal);
                if (reported[later] || reported[first]) continue;
                if (overlap(list[i].quad, list[j].quad) <= eps) continue;
                reported[later] = true;
                const Room& room = rooms[static_cast<std::size_t>(key.first)].room;
                check.error(portals[later].path / "center",
                            "its hole in the " + face_name(room, key.second) + " face of room " + quote(room.id) +
                                " overlaps the hole of portal " + quote(portals[first].portal.id) + " (portals[" +
                                std::to_string(first) + "])");
            }
        }
    }
}

}  // namespace

void check_holes(Checker& check, std::vector<PortalDraft>& portals, const std::vector<RoomDraft>& rooms) {
    FaceHoles holes;
    std::map<int, std::vector<FaceFrame>> prism_frames;  // by room, made once per room with portals
    for (std::size_t i = 0; i < portals.size(); ++i) {
        PortalDraft& draft = portals[i];
        const int room_index = draft.portal.room;
        // Volumes stand anywhere (layout-format.md, "Volume portals").
        if (!draft.rect_ok || room_index < 0 || draft.volume) continue;
        const RoomDraft& room = rooms[static_cast<std::size_t>(room_index)];
        if (!room.shape_ok) continue;
        if (!is_prism(room.room)) {
            find_box_hole(check, i, draft, room, holes);
            continue;
        }
        auto frames = prism_frames.find(room_index);
        if (frames == prism_frames.end()) frames = prism_frames.emplace(room_index, face_frames(room.room)).first;
        find_prism_hole(check, i, draft, room.room, frames->second, holes);
    }
    report_overlapping_holes(check, portals, rooms, holes);
}

}  // namespace impossible::layout::detail
