// One triangle covering the whole target at the far depth.
uniform float u_far_depth;  // 0 with reversed-Z, 1 with standard depth
void main() {
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(corner * 2.0 - 1.0, u_far_depth, 1.0);
}
