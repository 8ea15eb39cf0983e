// The props' shadows for the lit fragment shader (render/lights/shadow_maps.hpp):
// light_visible(g, p - L', d) is 1 when no prop lies between light image g's
// position L' and the point p at distance d = |p - L'| (in the lit room's
// coordinates; only the difference is needed, so any origin will do), 0 when
// one does; always 1 for an image without a map (no props on its path, or
// shadows off). The map holds the nearest prop's distance per texel; a point
// counts as lit when it is no farther than that plus a bias of some texels
// at distance d (a texel spans about shadow_texel = 2 / size radians) and a
// relative 1e-5: shadow_bias_texels plus SHADOW_SLOPE_TEXELS times the slope
// tan(incidence) when the caller passes the cosine of the incidence (the
// four-argument light_visible), or a fixed 2 · SHADOW_SLOPE_TEXELS without it.
//
// Only the LIGHTS variants compile it (it goes before lighting.frag.glsl,
// which then uses this light_visible instead of its own, always 1), and not
// LIGHTS_NO_SHADOWS, drawn where no prop's shadow can fall
// (render/lights/shadow_regions.hpp) or no image has a map; the
// renderer binds the maps for every frame of a lit layout
// (render/lights/shadow_maps.hpp, prepare_shadow_maps), with shadows off too.
#if defined(LIGHTS) && !defined(LIGHTS_NO_SHADOWS)
#define SHADOWS
// Texels of bias per unit of tan(incidence): a nearest texel's direction is
// within half a texel (along a diagonal, 0.71 texel) of the point's.
#define SHADOW_SLOPE_TEXELS 0.75
#if defined(WEBGL)
// WebGL 2 has neither cube map arrays nor storage buffers: the maps are a 2D
// array of six layers a cube (gl/webgl.cpp), the face picked here as GL
// picks a cube's face, and the buffer is a uniform block of the same words.
layout(binding = 3) uniform sampler2DArray u_shadow_maps;
layout(std140, binding = 6) uniform ShadowMapLayers {
    ivec4 shadow_words[1024];  // texel (float bits), bias (float bits), then the layers
};
#define shadow_word(k) shadow_words[(k) / 4][(k) % 4]
#define shadow_texel intBitsToFloat(shadow_word(0))
#define shadow_bias_texels intBitsToFloat(shadow_word(1))
float shadow_stored(vec3 r, int layer) {
    // The OpenGL specification's cube map face selection (table 8.19).
    vec3 a = abs(r);
    float sc, tc, ma;
    int face;
    if (a.x >= a.y && a.x >= a.z) {
        face = r.x >= 0.0 ? 0 : 1; ma = a.x; sc = r.x >= 0.0 ? -r.z : r.z; tc = -r.y;
    } else if (a.y >= a.z) {
        face = r.y >= 0.0 ? 2 : 3; ma = a.y; sc = r.x; tc = r.y >= 0.0 ? r.z : -r.z;
    } else {
        face = r.z >= 0.0 ? 4 : 5; ma = a.z; sc = r.z >= 0.0 ? r.x : -r.x; tc = -r.y;
    }
    vec2 st = 0.5 * (vec2(sc, tc) / ma + 1.0);
    return textureLod(u_shadow_maps, vec3(st, float(6 * layer + face)), 0.0).r;
}
#else
layout(binding = 3) uniform samplerCubeArray u_shadow_maps;
layout(std430, binding = 6) readonly buffer ShadowMapLayers {
    float shadow_texel;        // 2 / size: a texel's angle at a face's centre, radians
    float shadow_bias_texels;  // kShadowBiasTexels
    int shadow_layer[];        // per light image: its cube map, or -1
};
#endif

// The stored distance against d, with a bias of `texels` texels at d.
float shadow_test(int g, vec3 p_minus_lprime, float d, float texels) {
#if defined(WEBGL)
    if (g < 0 || g >= 4 * 1024 - 2) return 1.0;
    int layer = shadow_word(2 + g);
    if (layer < 0) return 1.0;
    float stored = shadow_stored(p_minus_lprime, layer);
#else
    if (g < 0 || g >= shadow_layer.length()) return 1.0;
    int layer = shadow_layer[g];
    if (layer < 0) return 1.0;
    float stored = textureLod(u_shadow_maps, vec4(p_minus_lprime, float(layer)), 0.0).r;
#endif
    return d <= stored + d * (shadow_texel * texels + 1e-5) ? 1.0 : 0.0;
}

// With the cosine of the angle of incidence (dot(n, w) > 0, which the caller
// has): the bias grows with the slope tan(incidence) that a half texel's
// error in direction turns into depth, so a lit face is never shadowed by
// itself (up to an incidence of 87°, where the light adds 5 % of head-on),
// and stays half a texel near head-on (props' contact shadows start there).
float light_visible(int g, vec3 p_minus_lprime, float d, float cos_incidence) {
    float c = clamp(cos_incidence, 0.05, 1.0);
    return shadow_test(g, p_minus_lprime, d, shadow_bias_texels + SHADOW_SLOPE_TEXELS * sqrt(1.0 - c * c) / c);
}

// Without it: a fixed bias of shadow_bias_texels + 2 · SHADOW_SLOPE_TEXELS
// texels (a lit face is not shadowed by itself up to an incidence of 63°).
float light_visible(int g, vec3 p_minus_lprime, float d) {
    return shadow_test(g, p_minus_lprime, d, shadow_bias_texels + 2.0 * SHADOW_SLOPE_TEXELS);
}
#endif
