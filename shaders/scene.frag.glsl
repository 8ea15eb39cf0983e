// The shading model of src/scene/shading.hpp (constants injected as defines),
// plus the cell id of the surface for the id map.
in vec3 v_checker_position;  // where the checker pattern is evaluated
in vec3 v_normal;
in vec3 v_color;
in float v_checker;
// MATERIALS: the variant for batches with a texture or an alpha cutoff. The
// plain variant has no discard, so that the driver may test depth before
// shading (llvmpipe tests it after a shader that can discard).
#if defined(MATERIALS)
in vec2 v_uv;      // texture coordinates, (0, 0) the image's top-left corner
in float v_alpha;  // alpha before the texel's

uniform sampler2D u_texture;
uniform bool u_textured;      // multiply by u_texture
uniform float u_alpha_cutoff; // alpha below it is not a surface; < 0: opaque
uniform bool u_mip_level0;    // colour from mip level 0 too (render::FrameDesc::textures_mip_level0)
#endif

uniform uint u_cell_id;
uniform bool u_unshaded;  // portal fill at the recursion limit: flat colour
uniform float u_exposure; // 2^EV: a surface's colour times it before its clamp (docs/lighting.md, "Exposure")

layout(location = 0) out vec4 o_color;
layout(location = 1) out uint o_id;

bool checker_dark(vec3 p, vec3 n, float side) {
    if (side <= 0.0) return false;
    // shading::checker_dark's rule: near-equal components tie, y first, then z.
    vec3 a = abs(n);
    vec2 uv = p.yz;
    if (a.y >= a.x - CHECKER_TIE && a.y >= a.z - CHECKER_TIE) uv = p.xz;
    else if (a.z >= a.x - CHECKER_TIE) uv = p.xy;
    ivec2 cell = ivec2(floor(uv / side));
    return ((cell.x + cell.y) & 1) != 0;
}

void main() {
#if defined(VOLUMES)
    clip_to_volumes();
#endif
    o_id = u_cell_id;
    if (u_unshaded) {
        o_color = vec4(v_color, 1.0);
        return;
    }
    vec3 base = v_color;
#if defined(MATERIALS)
    if (u_textured) {
        // Colour through the mipmaps; the cut-out test at mip level 0 with the
        // magnification filter, as the tracer samples (docs/tracer.md), so
        // that a surface's outline does not depend on its distance.
        base *= (u_mip_level0 ? textureLod(u_texture, v_uv, 0.0) : texture(u_texture, v_uv)).rgb;
        if (u_alpha_cutoff >= 0.0 && v_alpha * textureLod(u_texture, v_uv, 0.0).a < u_alpha_cutoff) discard;
    } else if (u_alpha_cutoff >= 0.0 && v_alpha < u_alpha_cutoff) {
        discard;
    }
#endif
    vec3 n = normalize(v_normal);
#if defined(LIGHTS)
    // layout-format.md, "Lights": the room's ambient and the light paths
    // (lighting.frag.glsl) instead of the built-in light.
    float dark = checker_dark(v_checker_position, n, v_checker) ? CHECKER_DARK : 1.0;
#if defined(LIGHTS_AMBIENT)
    vec3 lit = u_light_ambient;  // no light image reaches the room
#elif defined(LIGHTS_CACHED)
    vec3 lit = u_light_ambient + cached_light_sum(v_light_position, n, length(v_light_position + u_light_origin));
#else
    vec3 lit = u_light_ambient + light_sum(v_light_position, n, length(v_light_position + u_light_origin));
#endif
    o_color = vec4(clamp(base * dark * lit * u_exposure, 0.0, 1.0), 1.0);
#else
    float lambert = max(0.0, dot(n, LIGHT_DIR));
    float dark = checker_dark(v_checker_position, n, v_checker) ? CHECKER_DARK : 1.0;
    o_color = vec4(base * ((AMBIENT + DIFFUSE * lambert) * dark), 1.0);
    if (u_exposure != 1.0) o_color.rgb = clamp(o_color.rgb * u_exposure, 0.0, 1.0);
#endif
#if defined(VOLUMES)
    o_color.rgb *= u_volume_tint;
#endif
}
