// The light model of layout-format.md, "Lights", in double precision: what
// one light path adds to a surface point. The tracer evaluates it per shadow
// ray; the rasteriser's lit shader (shaders/lighting.frag.glsl) evaluates the
// same formulas in float, and src/lights enumerates the paths it sums.
//
//   colour       = clamp(base · dark · (ambient + Σ contribution), 0, 1)
//   contribution = color · intensity · factor · max(0, dot(n, w)) · att(d) · spot
//   att(d)       = 1 / d², times clamp(1 - (d / range)⁴, 0, 1) with a range
//   spot         = clamp((dot(s, -w_L) - cos outer) / (cos inner - cos outer), 0, 1)²
//
// (KHR_lights_punctual's range falloff and cone, without its 1/π.)
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "layout/layout.hpp"

namespace impossible::shading {

// A light path whose factor falls below one 8-bit step is not followed (the
// rule of window branches in sight, kMinBranchWeight).
inline constexpr double kMinLightFactor = 1.0 / 256.0;

// Surfaces this close to a shadow ray's start do not count:
// 1e-6 · (1 + |p|) (layout-format.md, "Lights", step 1).
inline double shadow_ray_start_tolerance(const glm::dvec3& p) { return 1e-6 * (1.0 + glm::length(p)); }

// att(d): the inverse square, times the range window when range > 0.
inline double light_attenuation(double d, double range) {
    const double inverse_square = 1.0 / (d * d);
    if (range <= 0.0) return inverse_square;
    const double r = d / range;
    const double r2 = r * r;
    return inverse_square * std::clamp(1.0 - r2 * r2, 0.0, 1.0);
}

// spot: `to_light` is the unit direction of the path's last leg towards the
// light, in the light's room's coordinates (1 for a point light).
inline double spot_factor(const layout::Light& light, const glm::dvec3& to_light) {
    if (!light.spot) return 1.0;
    const double pi = 3.14159265358979323846;
    const double cos_outer = std::cos(light.spot->outer_deg * pi / 180.0);
    const double cos_inner = std::cos(light.spot->inner_deg * pi / 180.0);
    const double s =
        std::clamp((glm::dot(light.spot->direction, -to_light) - cos_outer) / (cos_inner - cos_outer), 0.0, 1.0);
    return s * s;
}

// One path's contribution (before the clamp): `factor` is the path's product
// of portal factors (rgb), `d` the unfolded length, `w` the unit direction
// from the point towards the light's image, `n` the unit normal facing the
// viewer's side, `to_light` as for spot_factor.
inline glm::dvec3 light_contribution(const layout::Light& light, const glm::dvec3& factor, const glm::dvec3& n,
                                     const glm::dvec3& w, double d, const glm::dvec3& to_light) {
    const double lambert = std::max(0.0, glm::dot(n, w));
    return light.color *
           (light.intensity * lambert * light_attenuation(d, light.range) * spot_factor(light, to_light)) * factor;
}

// The final colour: base · dark · (ambient + sum), times the exposure's
// 2^EV (docs/lighting.md, "Exposure"), clamped per channel.
inline glm::dvec3 lit_color(const glm::dvec3& base, double dark, const glm::dvec3& ambient, const glm::dvec3& sum,
                            double exposure = 1.0) {
    return glm::clamp(base * dark * (ambient + sum) * exposure, 0.0, 1.0);
}

}  // namespace impossible::shading
