// Where the tracer's supersampled pixels take their rays (`trace --samples N`,
// docs/accuracy.md "Anti-aliasing"): the standard multisample positions of
// Direct3D 10.1+ and Vulkan for 1, 2, 4, 8 and 16 samples, on a 1/16-pixel
// grid. They are also what Mesa's llvmpipe reports for its 4 samples through
// glGetMultisamplefv(GL_SAMPLE_POSITION) and rasterises with, so that
// `trace --samples 4` and `render --samples 4` sample the same points and
// differ only where the rasteriser shades (once per pixel, at the centre).
//
// A position is in pixel units from the pixel's lower-left corner, x to the
// right and y up (GL window coordinates). In an image whose rows start at
// the top, sample (x, y) of pixel (i, j) lies at (i + x, j + 1 - y).
// No GL here: the tests of the pattern need no context.
#pragma once

#include <span>

namespace impossible::trace {

struct SamplePosition {
    double x = 0.5;
    double y = 0.5;
};

// The positions for 1, 2, 4, 8 or 16 samples (1: the pixel centre); empty
// for any other count.
std::span<const SamplePosition> sample_pattern(int samples);

}  // namespace impossible::trace
