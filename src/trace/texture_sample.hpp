// Reading a texture the way the tracer's colour rule needs it (docs/tracer.md,
// "Materials and textures"): at mip level 0 only, with the sampler's
// magnification filter, wrapped per axis as OpenGL defines REPEAT,
// CLAMP_TO_EDGE and MIRRORED_REPEAT (OpenGL 4.6 core, 8.14.2 "Coordinate
// Wrapping and Texel Selection"). Double precision, no allocation.
//
// Conventions: texture coordinates (s, t) put (0, 0) at the image's top-left
// corner, s to the right and t down; image row 0 (the top row) covers
// t in [0, 1/height). A texel's value is its bytes / 255, as stored (no sRGB
// decoding), in (r, g, b, a).
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "layout/layout.hpp"

namespace impossible::trace {

// The texel index along an axis of `size` texels (size > 0) for the whole
// texel coordinate `i` (a whole number, possibly negative or beyond size),
// wrapped by `wrap` (a assets::sampler_code wrap code; anything else is
// taken as REPEAT): REPEAT i mod size; CLAMP_TO_EDGE clamp(i, 0, size - 1);
// MIRRORED_REPEAT (size - 1) - mirror((i mod 2·size) - size), mirror(a) =
// a ≥ 0 ? a : -(1 + a). Not finite: 0.
int wrap_texel(double i, int size, int wrap);

// The texel (i, j), both already wrapped into the image, as bytes / 255.
glm::dvec4 texel(const image::Pixels& image, int i, int j);

// The image read at (s, t) at mip level 0 with the sampler's mag filter:
// NEAREST the texel (⌊s·w⌋, ⌊t·h⌋); LINEAR (any other code) GL's bilinear
// blend of the texels ⌊x⌋, ⌊x⌋ + 1 (and ⌊y⌋, ⌊y⌋ + 1) at x = s·w - 1/2,
// y = t·h - 1/2, weighted by the fractional parts; each index wrapped per
// axis. An empty image reads as white, (1, 1, 1, 1).
glm::dvec4 sample_mip0(const image::Pixels& image, const assets::Sampler& sampler, glm::dvec2 st);

inline glm::dvec4 sample_mip0(const assets::Texture& texture, glm::dvec2 st) {
    return sample_mip0(*texture.image, texture.sampler, st);
}

}  // namespace impossible::trace
