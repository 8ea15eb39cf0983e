// Internal to src/render: the light cache's tests of a cell (a convex flat
// quadrilateral, in its room's coordinates less the cell origin) against one
// light image (light_cache.hpp): whether its aperture and the shadows of its
// room's still props leave the cell wholly lit, wholly dark or neither.
// Conservative: a cell said to be lit or dark is so at every point.
#pragma once

#include <array>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "lights/light_images.hpp"
#include "scene/scene.hpp"

namespace impossible::render {

enum class CellLight { Lit, Dark, Edge };

// From the image's aperture alone (lighting.frag.glsl's light_aperture_open:
// beyond the aperture's plane, within the pyramid from L' through it); Lit
// for an image with no aperture. An image with more apertures is never
// cached (build_light_cache).
CellLight aperture_light(const lights::LightImage& image, const glm::dvec3& origin,
                         const std::array<glm::dvec3, 4>& corners);

// The same for any rectangle and light position: Lit where every segment
// from the cell to the light crosses the rectangle from its front.
CellLight through_rect(const math::PortalRect& rect, const glm::dvec3& position, const glm::dvec3& origin,
                       const std::array<glm::dvec3, 4>& corners);

// A prop's shadow hull (lights::shadow_region's 16 corners) with its faces.
// With the prop's box shrunk by the hull's margin (from_c maps the room's
// coordinates less the origin into the box's; lo > hi where the margin
// leaves nothing): a point whose segment to L' passes that box lies in the
// shadow by more than the maps' error, so every lookup finds it shadowed.
struct ShadowHull {
    std::array<glm::dvec3, 16> points{};
    std::vector<glm::dvec4> planes;  // n · x + w <= 0 inside
    glm::dvec3 lo{0.0}, hi{0.0};
    glm::dmat4 from_c{1.0};
    glm::dvec3 core_lo{0.0}, core_hi{-1.0};
};
ShadowHull make_hull(const std::array<glm::dvec3, 16>& corners);
// Whether the segment from p to `light` (both in the room's coordinates
// less the origin) passes the hull's shrunk box.
bool in_core_shadow(const ShadowHull& hull, const glm::dvec3& p, const glm::dvec3& light);
// Whether the hull may meet the cell (false: they are apart).
bool hull_meets(const ShadowHull& hull, const std::array<glm::dvec3, 4>& cell);

// Where an image's map may shadow: its legs' still props' hulls, as
// render/lights/shadow_regions.cpp makes them; `anywhere` where a prop
// holds the light. Nothing for map_size 0 (no prop shadows).
struct ImageShadows {
    bool anywhere = false;
    std::vector<ShadowHull> hulls;
};
ImageShadows image_shadows(const lights::LightImage& image, const std::vector<scene::CellObjects>& objects,
                           const glm::dvec3& origin, const std::pair<glm::dvec3, glm::dvec3>& bounds, int map_size);

// All tests: Lit only where the aperture lets all of the cell be lit, no
// blocker's shadow and no hull meets it; Dark where the aperture leaves all
// of it dark, one blocker hides all of it from the light, or all
// of it lies in one prop's core shadow (in_core_shadow at its corners: the
// shadow of a box from a point is convex).
CellLight cell_light(const lights::LightImage& image, const ImageShadows& shadows, const glm::dvec3& origin,
                     const std::array<glm::dvec3, 4>& corners);

// One image's term at p with unit normal n: lighting.frag.glsl's light_term
// with its test passed and no shadow, from its packed record (6 vec4s).
glm::dvec3 cached_term(const float* record, const glm::dvec3& p, const glm::dvec3& n);

}  // namespace impossible::render
