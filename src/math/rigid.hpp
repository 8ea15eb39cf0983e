// Rigid transforms (a rotation plus a translation) as dmat4.
//
// Conventions of conventions.hpp: column-major, p' = M · p, double precision.
// "Rigid" means the upper 3×3 is a proper rotation (orthonormal, det +1) and
// the last row is (0, 0, 0, 1).
#pragma once

#include "math/conventions.hpp"

namespace impossible::math {

// The exact-form inverse [Rᵀ | -Rᵀ·t] of a rigid transform.
dmat4 rigid_inverse(const dmat4& m);

// The nearest-in-spirit rigid transform: Gram–Schmidt on the 3×3 part (the
// first column is normalised, the second made orthogonal to it and
// normalised, the third is their cross product, so the result is
// right-handed), the translation kept and the last row reset to (0,0,0,1).
// Used to stop rounding from accumulating when transforms are chained.
dmat4 orthonormalize_rigid(const dmat4& m);

// max |(RᵀR - I)_ij| of the 3×3 part: 0 for an exactly orthonormal one.
double orthonormality_error(const dmat4& m);

// max |m_ij - n_ij| over all sixteen entries.
double max_abs_difference(const dmat4& m, const dmat4& n);

}  // namespace impossible::math
