// The hidden-area mask (src/render/hidden_mask.hpp): drawn once a frame over
// the whole target with colour and ids masked, it sets the stencil to the
// hidden value wherever the mask texture (both eyes side by side, rows from
// the bottom) says the pixel is hidden, and nowhere else. One fragment per
// pixel, so every sample of a hidden pixel is masked, as the tracer masks the
// whole pixel.
uniform usampler2D u_mask;

void main() {
    if (texelFetch(u_mask, ivec2(gl_FragCoord.xy), 0).r == 0u) discard;
}
