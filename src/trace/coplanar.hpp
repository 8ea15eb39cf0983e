// Coplanar ties between a door's box and a room's or prop's face for the
// tracer (layout-format.md, "What a pixel shows", coplanar surfaces; the
// rasteriser's side is in docs/choices.md). Internal to src/trace.
#pragma once

#include <cmath>

#include <glm/geometric.hpp>

#include "trace/trace_scene.hpp"

namespace impossible::trace {

// A surface's part in a coplanar tie (layout-format.md, "What a pixel shows",
// coplanar surfaces): where a door's box and a room's or prop's face meet a
// ray at the same point, the box's inner face wins and its front face loses.
// "The same point" is within the door's tolerance (1e-9 · (1 + |centre|),
// ScenePortal::clip_tolerance) of the box face's plane, the distance within
// which the clip plane of the view through the door drops a point too: a
// surface that ties with the front face is one that the continued ray would
// find clipped. Along the ray that is tolerance / |dir · normal|. Surfaces
// of one rank keep the order of the search (the first at the smallest t),
// as before these rules; mirrors and windows rank as surfaces.
struct Tie {
    enum Rank { DoorFront = 0, Surface = 1, DoorInner = 2 };
    Rank rank = Surface;
    double tolerance = 0.0;  // in units of t; 0 for a surface
};

// Whether a hit at t of tie `tie` replaces the one kept at kept_t.
inline bool replaces(double t, const Tie& tie, double kept_t, const Tie& kept) {
    if (tie.rank == kept.rank) return t < kept_t;
    const double tolerance = tie.tolerance > kept.tolerance ? tie.tolerance : kept.tolerance;
    if (t < kept_t - tolerance) return true;
    if (t > kept_t + tolerance) return false;
    return tie.rank > kept.rank;
}

// How far a search must look past a hit kept at t: a door's front face loses
// to a surface up to its tolerance behind it.
inline double search_limit(double t, const Tie& kept) { return kept.rank == Tie::DoorFront ? t + kept.tolerance : t; }

// The tie of a door box's face of normal `normal` met by a ray along `dir`.
inline Tie box_tie(const ScenePortal& portal, bool inner, const dvec3& normal, const dvec3& dir) {
    if (portal.kind != layout::PortalKind::Door) return Tie{};
    const double across = std::abs(glm::dot(dir, normal));
    return Tie{inner ? Tie::DoorInner : Tie::DoorFront, portal.clip_tolerance / across};
}

// The tie of a room face's hit, met in the hole of `portal` (or -1): a
// door's front face there.
inline Tie face_tie(const Scene& scene, int portal, const dvec3& dir) {
    if (portal < 0) return Tie{};
    const ScenePortal& p = scene.portals[portal];
    return box_tie(p, false, p.rect.normal, dir);
}

}  // namespace impossible::trace
