// The hidden-area mask (src/render/targets/hidden_mask.hpp): trapezoids that cover
// exactly the hidden pixels' centres (or, multisampled, every sample of each
// hidden pixel), in the side-by-side target's normalised device coordinates.
layout(location = 0) in vec2 a_position;

void main() { gl_Position = vec4(a_position, 0.0, 1.0); }
