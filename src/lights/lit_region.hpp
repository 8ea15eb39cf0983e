// Where a light image's path can light room C at all, for the rasteriser's
// split of a lit room's draws (render/objects/object_draw.cpp): every point
// its light reaches lies on a ray from the image L' through the path's first
// aperture P1 (the one nearest the surface), beyond P1. Bounded by a far
// distance past the room, that set is a truncated pyramid: P1's four corners
// and the same corners pushed out along their rays from L'. Conservative: the
// path's other apertures, its blockers, the light's range and its spot cone
// only make the lit set smaller.
#pragma once

#include <array>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "lights/light_images.hpp"

namespace impossible::lights {

struct LitRegion {
    enum class Kind {
        Pyramid,     // within `corners`
        Nowhere,     // L' lies in front of P1: no segment from C passes P1 from its front
        Everywhere,  // no apertures (it may light all of C), or L' within kMinApertureDistance of P1's plane
    };
    Kind kind = Kind::Everywhere;
    // As math::box_corners orders a box's: P1's rectangle, then the far one;
    // in C's coordinates.
    std::array<glm::dvec3, 8> corners{};
};

// `room_min`, `room_max`: C's bounding box.
LitRegion lit_region(const LightImage& image, const glm::dvec3& room_min, const glm::dvec3& room_max);

// A distance from L' that every point of room C lies within, with a margin
// for hands and objects reaching past its walls: how far lit_region's
// pyramid and shadow_region's hull must reach.
double light_reach(const glm::dvec3& light, const glm::dvec3& room_min, const glm::dvec3& room_max);

inline constexpr double kMinApertureDistance = 1e-6;

// Where an occluder may shadow a point from a light at L': behind it on rays
// from L', the box and the same box pushed away from L' far enough to pass
// every point within `reach` of L' (the convex hull of the 16 corners holds
// that part of its shadow). The box is [lo, hi] in its own coordinates,
// which `from_box` maps to the points' (a rigid map), grown on every side by
// `grow_angle` times its farthest distance from L', and 0.1 mm (a shadow
// map's lookup reads a texel near the point's direction, not at it);
// `corners_out` is in the points' coordinates. False where L' lies within
// kMinApertureDistance of the grown box (its shadow may be anywhere).
bool shadow_region(const glm::dvec3& light, const glm::dmat4& from_box, glm::dvec3 lo, glm::dvec3 hi, double reach,
                   double grow_angle, std::array<glm::dvec3, 16>& corners_out);

}  // namespace impossible::lights
