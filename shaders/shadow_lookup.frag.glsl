// The props' shadows for the lit fragment shader (render/shadow_maps.hpp):
// light_visible(g, p - L', d) is 1 when no prop lies between light image g's
// position L' and the point p at distance d = |p - L'| (in the lit room's
// coordinates; only the difference is needed, so any origin will do), 0 when
// one does; always 1 for an image without a map (no props on its path, or
// shadows off). The map holds the nearest prop's distance per texel; a point
// counts as lit when it is no farther than that plus a bias of
// bias_texels texels at distance d (a texel spans about 2 / size radians)
// and a relative 1e-5, so that a lit prop face is not shadowed by itself up
// to an incidence of atan(2 · bias_texels).
//
// Only the LIGHTS variants compile it (it goes before lighting.frag.glsl,
// which then uses this light_visible instead of its own, always 1); the
// renderer binds the maps for every frame of a lit layout
// (render/shadow_maps.hpp, prepare_shadow_maps), with shadows off too.
#if defined(LIGHTS)
#define SHADOWS
layout(binding = 3) uniform samplerCubeArray u_shadow_maps;
layout(std430, binding = 6) readonly buffer ShadowMapLayers {
    float shadow_texel;        // 2 / size: a texel's angle at a face's centre, radians
    float shadow_bias_texels;  // kShadowBiasTexels
    int shadow_layer[];        // per light image: its cube map, or -1
};

float light_visible(int g, vec3 p_minus_lprime, float d) {
    if (g < 0 || g >= shadow_layer.length()) return 1.0;
    int layer = shadow_layer[g];
    if (layer < 0) return 1.0;
    float stored = textureLod(u_shadow_maps, vec4(p_minus_lprime, float(layer)), 0.0).r;
    float bias = d * (shadow_texel * shadow_bias_texels + 1e-5);
    return d <= stored + bias ? 1.0 : 0.0;
}
#endif
