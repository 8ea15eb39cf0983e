// Shows one eye of the side-by-side view (left eye in the left half), or both
// as a red-cyan anaglyph: red from the left eye's luminance (a "half-colour"
// anaglyph, which rivals less than the left eye's plain red channel), green
// and blue from the right eye.
in vec2 v_uv;
uniform sampler2D u_view;
uniform int u_eye;  // 0 left, 1 right, -1 anaglyph
layout(location = 0) out vec4 o_color;
void main() {
    vec3 left = texture(u_view, vec2(v_uv.x * 0.5, v_uv.y)).rgb;
    vec3 right = texture(u_view, vec2(0.5 + v_uv.x * 0.5, v_uv.y)).rgb;
    if (u_eye == 0) o_color = vec4(left, 1.0);
    else if (u_eye == 1) o_color = vec4(right, 1.0);
    else o_color = vec4(dot(left, vec3(0.299, 0.587, 0.114)), right.g, right.b, 1.0);
}
