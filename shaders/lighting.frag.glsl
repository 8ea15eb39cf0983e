// The lit colour of layout-format.md, "Lights" (src/shading/lighting.hpp's
// formulas in float), for the LIGHTS variants of scene.frag.glsl:
// render/programs/scene_program.cpp puts it before the fragment shader, after the
// volume test. Only the LIGHTS variants compile it; every other variant's
// text is as before.
#if defined(LIGHTS)
// The fragment in the coordinates of the room it belongs to (the room that
// lights it), less that room's cell origin.
in vec3 v_light_position;

// Every room's light images (render/lights/light_buffers.hpp), room after room, six
// vec4s each, positions relative to the room's cell origin:
//   [0] xyz: the image L', w: range (0: none)
//   [1] rgb: color · intensity · factor, w: cos outer (2: a point light)
//   [2] xyz: the spot's axis in the room's coordinates, w: 1 / (cos inner - cos outer)
//   [3] x: the first of its path's rectangles, y: their number (as floats);
//       in a LIGHTS_SINGLE_APERTURE room's path image, z: k, w: a
//   [4], [5]: such an image's one aperture (light_aperture_open): [4] xyz:
//       its normal n, w: b; [5] xyz: its right axis r', w: width / height
// LIGHT_UBO: the same as uniform blocks, which llvmpipe reads faster (where
// they fit in LIGHT_UBO_VEC4S vec4s each).
// LIGHTS_AMBIENT (a room no light image reaches): the ambient alone, no
// buffers (WebGL has no storage buffers) and no loop.
#if !defined(LIGHTS_AMBIENT)
#if defined(LIGHT_UBO)
layout(std140, binding = 4) uniform LightImages {
    vec4 light_images[LIGHT_UBO_VEC4S];
};
#else
layout(std430, binding = 4) readonly buffer LightImages {
    vec4 light_images[];
};
#endif
// The portal rectangles of the paths: four vec4s each, the centre (w: 1 for
// a blocker, 0 for an aperture), the normal (towards the surface's side),
// and the right and up axes divided by the half width and height.
#if defined(LIGHT_UBO)
layout(std140, binding = 5) uniform LightRects {
    vec4 light_rects[LIGHT_UBO_VEC4S];
};
#else
layout(std430, binding = 5) readonly buffer LightRects {
    vec4 light_rects[];
};
#endif
#endif  // !LIGHTS_AMBIENT
uniform int u_light_first;   // the room's first image in light_images
uniform int u_light_count;   // its number of images
uniform int u_light_direct;  // its first images, with no apertures (light_sum)
uniform vec3 u_light_ambient;
uniform vec3 u_light_origin;  // the room's cell origin (layout coordinates of p = origin + p)

#if !defined(LIGHTS_AMBIENT)
#if !defined(SHADOWS)
// Without shaders/shadow_lookup.frag.glsl before this (which defines
// SHADOWS and its own light_visible), light passes props as if they were
// not there.
float light_visible(int image, vec3 p_minus_light, float d) { return 1.0; }
#endif

// Where the segment p + t·v crosses rectangle r from its front side: its t,
// or -1 where it misses the rectangle (edges included for a blocker, not for
// an aperture) or meets it from behind. Without branches, so that the loops
// over the images and rectangles stay uniform: their buffer reads are then
// one read for every fragment of a batch rather than one per fragment.
float light_rect_crossing(int r, vec4 c, vec3 p, vec3 v) {
    int b = 4 * r;
    vec3 n = light_rects[b + 1].xyz;
    float dn = dot(n, v);
    float t = dot(n, c.xyz - p) / min(dn, -1e-30);
    vec3 x = p + t * v - c.xyz;
    vec2 q = abs(vec2(dot(x, light_rects[b + 2].xyz), dot(x, light_rects[b + 3].xyz)));
    bool inside = c.w > 0.5 ? max(q.x, q.y) <= 1.0 : max(q.x, q.y) < 1.0;
    return dn < 0.0 && inside ? t : -1.0;
}

// Whether the segment from p to the image (p + v) passes the image's
// apertures in order from their fronts, and meets none of its blockers on
// their legs (lights::segment_passes in float). The image's rectangles come
// leg by leg: the blockers of leg j (w = 1), then aperture j (w = 0), and
// the last leg's blockers. t0: a blocker this close to p (as a share of v)
// does not count.
bool light_path_open(vec4 ranges, vec3 p, vec3 v, float t0) {
    int first = int(ranges.x), end = first + int(ranges.y);
    float low = t0;      // blockers count beyond it on this leg
    float leg_start = 0.0;
    float block = 2.0;   // the nearest blocker crossing on this leg
    bool open = true;
    int r = first;
    if (r < end) {
        do {
            vec4 c = light_rects[4 * r];
            float t = light_rect_crossing(r, c, p, v);
            if (c.w > 0.5) {
                block = t > low ? min(block, t) : block;
            } else {
                open = open && t > leg_start && t < 1.0 && block >= t;
                leg_start = t;
                low = t;
                block = 2.0;
            }
        } while (++r < end);
    }
    return open && block >= 1.0;
}

// The same for an image with one aperture and no blocker: whether the
// segment from p to the image (p + v) crosses the aperture from its front,
// edges excluded. The aperture is stored with the image (vec4s 3 to 5, from
// the image's side): the crossing is x = L' + s (p - L') with
// s = k / (n · (p - L')), k = n · (c - L'), inside where
// |a + s r' · (p - L')| < 1 and |b + s u' · (p - L')| < 1 for the right and up
// axes over the half extents r', u' (u' = (n × r') · width / height), with
// a = r' · (L' - c), b = u' · (L' - c); on the segment where 0 < s < 1. Three
// reads of the image's own record, where the loop reads its rectangle's
// index and then the rectangle.
bool light_aperture_open(int b, vec3 v) {
    vec4 k_a = light_images[b + 3];
    vec4 normal_b = light_images[b + 4];
    vec4 right_aspect = light_images[b + 5];
    vec3 w = -v;  // p - L'
    float dn = dot(normal_b.xyz, w);
    float s = k_a.z / max(dn, 1e-30);
    vec3 up = cross(normal_b.xyz, right_aspect.xyz) * right_aspect.w;
    vec2 q = abs(vec2(k_a.w, normal_b.w) + s * vec2(dot(w, right_aspect.xyz), dot(w, up)));
    return dn > 0.0 && s > 0.0 && s < 1.0 && max(q.x, q.y) < 1.0;
}

// Which test an image's term makes (a constant at each call).
const int kNoTest = 0;        // no rectangle: a light of the room itself seen directly
const int kPathTest = 1;      // its rectangles in order (light_path_open)
const int kApertureTest = 2;  // its one aperture (light_aperture_open)

// One image's contribution at the point p (relative to the room's origin)
// with unit normal n, with the test `test`.
vec3 light_term(int g, vec3 p, vec3 n, float origin_distance, int test) {
    int b = 6 * g;
    vec4 position = light_images[b];
    vec3 v = position.xyz - p;
    float d = max(length(v), 1e-30);
    vec3 w = v / d;
    float att = 1.0 / (d * d);
    vec4 radiance = light_images[b + 1];
#if defined(LIGHTS_PLAIN_POINTS)
    // Every image of the room is a point light without a range: its range
    // and spot factors would be exactly 1 (render::kLightsPlainPoints).
    float amount = max(0.0, dot(n, w)) * att;
#else
    float r = d / max(position.w, 1e-30);
    float r2 = r * r;
    att *= position.w > 0.0 ? clamp(1.0 - r2 * r2, 0.0, 1.0) : 1.0;
    vec4 axis = light_images[b + 2];
    float spot = clamp((dot(axis.xyz, -w) - radiance.w) * axis.w, 0.0, 1.0);
    spot = radiance.w <= 1.0 ? spot * spot : 1.0;
    float amount = max(0.0, dot(n, w)) * att * spot;
#endif
#if defined(LIGHTS_NAIVE)
    // render::FrameDesc::naive_lights: every image reaches every point
    // (a baseline for the cost of the test, never a mode to view).
    bool open = true;
#else
    bool open = test == kNoTest ||
                (test == kApertureTest ? light_aperture_open(b, v)
                                       : light_path_open(light_images[b + 3], p, v, 1e-6 * (1.0 + origin_distance) / d));
#endif
    return radiance.rgb * (open ? amount * light_visible(g, p - position.xyz, d) : 0.0);
}

// Σ contribution over the room's images, for the point p (relative to the
// room's origin) with unit normal n; `origin_distance` is |p| in layout
// coordinates, for the shadow ray's start tolerance. The room's first
// u_light_direct images have no apertures (its own lights, seen directly):
// their loop has no path test, unless one has blockers
// (LIGHTS_DIRECT_BLOCKERS). llvmpipe runs every branch of a condition,
// taken or not (masked), and a loop's body once more after its last
// iteration, so what a fragment costs is the code it passes, not the code it
// takes: the loops are do-while loops, each at least one iteration long, and
// a room with only one kind of image draws with the variant that has only
// that loop (LIGHTS_NO_DIRECT, LIGHTS_NO_PATHS: render/lights/light_draw.cpp).
vec3 light_sum(vec3 p, vec3 n, float origin_distance) {
    vec3 sum = vec3(0.0);
    int i = 0;
#if !defined(LIGHTS_NO_DIRECT)
    do {
#if defined(LIGHTS_DIRECT_BLOCKERS)
        sum += light_term(u_light_first + i, p, n, origin_distance, kPathTest);
#else
        sum += light_term(u_light_first + i, p, n, origin_distance, kNoTest);
#endif
    } while (++i < u_light_direct);
#endif
#if !defined(LIGHTS_NO_PATHS)
    do {
#if defined(LIGHTS_SINGLE_APERTURE)
        // Every path image has one aperture and no blocker
        // (render::kLightsSingleAperture).
        sum += light_term(u_light_first + i, p, n, origin_distance, kApertureTest);
#else
        sum += light_term(u_light_first + i, p, n, origin_distance, kPathTest);
#endif
    } while (++i < u_light_count);
#endif
    return sum;
}

#if defined(LIGHTS_CACHED)
// The light cache (render/lights/light_cache.hpp): per cell of the atlas,
// the sum of the images that reach all of it, unshadowed, at its four
// corners (texels 2x + i, 2y + j), interpolated bilinearly by the linear
// filter; and a bit for each image whose aperture, blocker or prop shadow
// may cross the cell, whose term is added here exactly. Most cells have no
// bit: the loops then run no iteration.
in vec2 v_light_cell;
uniform highp sampler2D u_light_cache;
uniform highp usampler2D u_light_edges;

vec3 cached_light_sum(vec3 p, vec3 n, float origin_distance) {
    ivec2 cell = ivec2(floor(v_light_cell));
    vec2 f = clamp(v_light_cell - vec2(cell), 0.0, 1.0);
    // Between the centres of the cell's four texels, the linear filter is
    // the bilinear interpolation of its corners: one lookup, not four.
    vec2 at = (2.0 * vec2(cell) + 0.5 + f) / vec2(textureSize(u_light_cache, 0));
    vec3 sum = textureLod(u_light_cache, at, 0.0).rgb;
    uint bits = texelFetch(u_light_edges, cell, 0).r;
    // The room's own lights, then its path images (one aperture each and
    // no blocker: build_light_cache caches no other room).
    uint direct = u_light_direct >= 32 ? 0xffffffffu : (1u << uint(u_light_direct)) - 1u;
    uint own = bits & direct;
    while (own != 0u) {
        int g = findLSB(own);
        own &= own - 1u;
#if defined(LIGHTS_DIRECT_BLOCKERS)
        sum += light_term(u_light_first + g, p, n, origin_distance, kPathTest);
#else
        sum += light_term(u_light_first + g, p, n, origin_distance, kNoTest);
#endif
    }
    uint paths = bits & ~direct;
    while (paths != 0u) {
        int g = findLSB(paths);
        paths &= paths - 1u;
        sum += light_term(u_light_first + g, p, n, origin_distance, kApertureTest);
    }
    return sum;
}
#endif  // LIGHTS_CACHED
#endif  // !LIGHTS_AMBIENT
#endif
