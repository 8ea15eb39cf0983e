// A bumpy sphere of about N triangles as a glTF 2.0 binary (.glb), built in
// code, for measuring the tracer on large models without downloading one:
// radius about 1 m, centred on the origin, one material, smooth vertex
// normals, 32-bit indices. The bytes are the same on every run and platform
// (little-endian).
#pragma once

#include <vector>

namespace impossible::tools {

// At most `triangles` triangles (at least 16 are asked for): `stacks` rings
// of 2 · stacks quads, with stacks = floor(sqrt(triangles / 4)), and one
// triangle for each quad that touches a pole: 4 · stacks² - 4 · stacks.
std::vector<unsigned char> make_sphere_glb(long triangles);

}  // namespace impossible::tools
