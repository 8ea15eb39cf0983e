// Writes depth only (colour writes are masked by the pass state).
layout(location = 0) out vec4 o_color;
void main() { o_color = vec4(0.0); }
