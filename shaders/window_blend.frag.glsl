// A window's reflected view, copied aside before the view through it was
// drawn, scaled by the reflectance r; the blend adds it to (1 - r) · tint ·
// the colour there (render/portals/portal_glass.cpp). A reflected view cut by the
// branch-weight rule is a constant (the fill colour) instead of the copy.
#if defined(SAVED_MULTISAMPLE)
uniform sampler2DMS u_saved;
#else
uniform sampler2D u_saved;
#endif
uniform bool u_use_saved;
uniform vec3 u_scale;     // r
uniform vec3 u_constant;  // r · the fill colour, when !u_use_saved

layout(location = 0) out vec4 o_color;

void main() {
    if (!u_use_saved) {
        o_color = vec4(u_constant, 0.0);
        return;
    }
#if defined(SAVED_MULTISAMPLE)
    vec3 saved = texelFetch(u_saved, ivec2(gl_FragCoord.xy), gl_SampleID).rgb;
#else
    vec3 saved = texelFetch(u_saved, ivec2(gl_FragCoord.xy), 0).rgb;
#endif
    o_color = vec4(u_scale * saved, 0.0);
}
