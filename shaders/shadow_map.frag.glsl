// The distance from the light's image to the nearest prop surface, per texel
// of a cube shadow map's face (render/lights/shadow_maps.hpp). Cut-outs drop the
// fragments whose alpha is below the cutoff, read at mip level 0 as the
// tracer reads it.
in vec3 v_relative;
in vec2 v_uv;
in float v_alpha;

layout(binding = 2) uniform sampler2D u_texture;
uniform bool u_textured;
uniform float u_alpha_cutoff;  // < 0: opaque

layout(location = 0) out float o_distance;

void main() {
    if (u_alpha_cutoff >= 0.0) {
        float alpha = v_alpha * (u_textured ? textureLod(u_texture, v_uv, 0.0).a : 1.0);
        if (alpha < u_alpha_cutoff) discard;
    }
    o_distance = length(v_relative);
}
