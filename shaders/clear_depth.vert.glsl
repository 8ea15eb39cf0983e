// One triangle covering the whole target at the far depth; or, with
// u_eye_quads, one rectangle per instance (u_rects, in the viewport's
// normalised device coordinates), so that a portal's depth reset covers each
// eye's part and not the seam between them.
uniform float u_far_depth;  // 0 with reversed-Z, 1 with standard depth
uniform bool u_eye_quads;
uniform vec4 u_rects[2];    // (x0, y0, x1, y1) per instance
void main() {
    if (u_eye_quads) {
        vec4 r = u_rects[gl_InstanceID];
        int k = gl_VertexID;  // two triangles: (x0,y0) (x1,y0) (x1,y1), (x0,y0) (x1,y1) (x0,y1)
        bool right = k == 1 || k == 2 || k == 4;
        bool top = k == 2 || k == 4 || k == 5;
        gl_Position = vec4(right ? r.z : r.x, top ? r.w : r.y, u_far_depth, 1.0);
        return;
    }
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(corner * 2.0 - 1.0, u_far_depth, 1.0);
}
