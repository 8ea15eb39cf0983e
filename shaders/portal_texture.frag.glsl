// Render-to-texture portals: the portal's box shows the texture its view was
// rendered into, looked up at the fragment's own place in the side-by-side
// target (the texture holds both eyes side by side, like the target).
uniform sampler2D u_color_texture;
uniform usampler2D u_id_texture;
uniform vec2 u_target_size;  // the main target's size in pixels

layout(location = 0) out vec4 o_color;
layout(location = 1) out uint o_id;

void main() {
#if defined(VOLUMES)
    clip_to_volumes();
#endif
    vec2 uv = gl_FragCoord.xy / u_target_size;
    o_color = vec4(texture(u_color_texture, uv).rgb, 1.0);
    o_id = texture(u_id_texture, uv).r;
}
