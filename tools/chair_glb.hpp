// A small chair as a glTF 2.0 binary (.glb), built in code so the project
// ships a model without downloading one: four legs, a seat and a back in a
// wood material, and a cushion in a fabric material, each box with flat
// normals. The bytes are the same on every run and platform (little-endian).
#pragma once

#include <vector>

namespace impossible::tools {

std::vector<unsigned char> make_chair_glb();

}  // namespace impossible::tools
