// The one shading model shared by the rasteriser's fragment shader and the
// reference tracer, so that both produce the same colour for the same surface:
//
//   colour = base * (kAmbient + kDiffuse * max(0, dot(normal, kLightDir)))
//            * (checker dark square ? kCheckerDark : 1)
//
// The checker pattern uses the two world coordinates that lie in the face's
// plane (the axes other than the normal's dominant axis), so a face's constant
// coordinate never flips the parity by rounding: square (a, b) is dark when
// floor(a / side) + floor(b / side) is odd. Components within kCheckerAxisTie
// of each other tie, and a tie goes to y, then z: a prism wall at 45° has
// |n.x| = |n.z| up to rounding, which the shader's float normal (interpolated
// per pixel) and the tracer's double one would break differently, pixel by
// pixel.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "layout/layout.hpp"

namespace impossible::shading {

// Direction towards the light (unit): from above, slightly from +X and +Z.
inline const glm::dvec3 kLightDir = glm::normalize(glm::dvec3(0.3, 0.9, 0.4));
inline constexpr double kAmbient = 0.45;
inline constexpr double kDiffuse = 0.55;
inline constexpr double kCheckerDark = 0.75;
inline constexpr double kCheckerAxisTie = 1e-4;

// What a pixel shows when the recursion limit is reached, and its id in the
// id map (rooms have 1 + their index, below it; the rasteriser and the tracer
// both write it).
inline const glm::dvec3 kPortalFillColor{0.24, 0.22, 0.30};
inline constexpr std::uint8_t kFillId = 255;
// What a pixel shows where no surface is hit (id 0).
inline const glm::dvec3 kBackgroundColor{0.0, 0.0, 0.0};

// A window's two branches (layout-format.md, "What a pixel shows", step 5)
// are weighted: the through branch by (1 - r) · tint, the reflected one by r;
// a mirror multiplies by its tint. The weight of a view is the product of
// these factors from the eye (the largest channel of each tint). Two facing
// windows branch at every level, 2^depth views; so a window branch whose
// weight would fall below kMinBranchWeight (one 8-bit step) is not followed
// and shows the fill colour, as at the recursion limit (kFillId for a through
// branch). The rasteriser and the tracer apply the same rule.
inline constexpr double kMinBranchWeight = 1.0 / 256.0;

inline double max_channel(const glm::dvec3& c) { return std::max(c.x, std::max(c.y, c.z)); }

inline bool checker_dark(const glm::dvec3& position, const glm::dvec3& normal, double side) {
    if (side <= 0.0) return false;
    const glm::dvec3 a = glm::abs(normal);
    const double tie = kCheckerAxisTie;
    double u = position.y, v = position.z;  // normal mostly along x
    if (a.y >= a.x - tie && a.y >= a.z - tie) {
        u = position.x;
        v = position.z;
    } else if (a.z >= a.x - tie) {
        u = position.x;
        v = position.y;
    }
    const long long parity =
        static_cast<long long>(std::floor(u / side)) + static_cast<long long>(std::floor(v / side));
    return (parity & 1) != 0;
}

// Where a point of a room face falls in the face's texture (layout-format.md,
// `textures`), in tiles: (s, t) with s growing to the right of a viewer inside
// the room facing the face, t growing downwards on walls and towards +z on
// the floor and ceiling (the image's top towards -z), one unit per
// `texture_size` metres. Tile edges lie at whole s and t, which are whole
// multiples of texture_size in layout coordinates; a texel is found from the
// fractional part (the image's top-left corner at (0, 0)).
inline glm::dvec2 room_texture_uv(layout::Face face, const glm::dvec3& p, double size) {
    switch (face) {
        case layout::Face::Floor: return glm::dvec2(p.x, p.z) / size;
        case layout::Face::Ceiling: return glm::dvec2(-p.x, p.z) / size;
        case layout::Face::NegX: return glm::dvec2(-p.z, -p.y) / size;
        case layout::Face::PosX: return glm::dvec2(p.z, -p.y) / size;
        case layout::Face::NegZ: return glm::dvec2(p.x, -p.y) / size;
        case layout::Face::PosZ: return glm::dvec2(-p.x, -p.y) / size;
    }
    return glm::dvec2(0.0);
}

// A surface's colour under the exposure `scale` = 2^EV (docs/lighting.md,
// "Exposure"): times it, clamped to 0..1; unchanged at 1.
inline glm::dvec3 exposed(const glm::dvec3& color, double scale) {
    return scale == 1.0 ? color : glm::clamp(color * scale, 0.0, 1.0);
}

inline glm::dvec3 shade(const glm::dvec3& base, const glm::dvec3& normal, const glm::dvec3& position, double checker) {
    const double lambert = std::max(0.0, glm::dot(normal, kLightDir));
    const double dark = checker_dark(position, normal, checker) ? kCheckerDark : 1.0;
    return base * ((kAmbient + kDiffuse * lambert) * dark);
}

}  // namespace impossible::shading
