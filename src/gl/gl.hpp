// The one include for GL calls. Native builds: glad's generated GL 4.5 core
// loader. The web build (emscripten): WebGL 2 (OpenGL ES 3.0) with the GL 4.5
// calls the renderer makes mapped onto it (gl/webgl.hpp).
#pragma once

#if defined(__EMSCRIPTEN__)
#include "gl/webgl.hpp"
#else
#include <glad/gl.h>
#endif
