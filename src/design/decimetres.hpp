// Numbers as the generated layouts write them: lengths kept as whole
// decimetres while planning, and values rounded to hundredths, so that the
// JSON text is short and the same on every machine.
#pragma once

#include <cmath>

namespace impossible::design {

inline double dm(int v) { return v / 10.0; }
inline double cents(double v) { return std::round(v * 100.0) / 100.0; }

}  // namespace impossible::design
