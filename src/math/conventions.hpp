// Conventions of src/math (pure math: no GL, no I/O).
//
// - Units: metres; angles in the API are degrees unless a name says radians.
// - Right-handed coordinates, +Y up; a viewer with yaw 0 looks along -Z.
// - glm matrices are column-major and act on column vectors: p' = M * p.
// - Everything is double precision; renderers convert to float at the end.
// - Eye space: the eye at the origin looking along -Z, +Y up, +X right
//   (OpenGL convention).
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace impossible::math {

using glm::dmat3;
using glm::dmat4;
using glm::dvec3;
using glm::dvec4;

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double radians(double deg) { return deg * (kPi / 180.0); }

}  // namespace impossible::math
