// The one include for GL calls: glad's generated GL 4.5 core loader.
#pragma once

#include <glad/gl.h>
