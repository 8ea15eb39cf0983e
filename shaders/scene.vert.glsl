// Single-pass stereo: every draw has two instances, and the instance picks the
// eye. STEREO_CLIP_SHIFT (default) squeezes each eye's clip-space x into its
// half of the side-by-side target; STEREO_VIEWPORT_INDEX writes
// gl_ViewportIndex instead (ARB_shader_viewport_layer_array); STEREO_SINGLE_EYE
// draws one eye (u_single_eye) into the current viewport, for two-pass renders.
#if defined(STEREO_VIEWPORT_INDEX)
#extension GL_ARB_shader_viewport_layer_array : require
#endif

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_color;
layout(location = 3) in float a_checker;
#if defined(MATERIALS)
layout(location = 4) in vec2 a_uv;
layout(location = 5) in float a_alpha;
#endif

uniform mat4 u_view_proj[2];
// Per eye: the part of the eye image this draw may touch, as an NDC rectangle
// (x0, y0, x1, y1), clipped exactly with four clip distances; an empty
// rectangle drops the draw for that eye.
uniform vec4 u_eye_rect[2];
// Per eye: a plane in this cell's coordinates; only points with
// dot(plane, (p, 1)) >= 0 are drawn. (0, 0, 0, 1) clips nothing.
uniform vec4 u_clip_plane[2];
// Positions are relative to the cell's origin (scene::CellFrame::origin); the checker
// pattern is that of origin + p, and origin modulo the pattern's period is
// this offset.
uniform vec3 u_checker_offset;
uniform int u_single_eye;
// OBJECT_CUTS: instances of dynamic objects (walk/objects.hpp), many in one
// draw (render/objects/instance_stream.hpp): each vertex's mesh (its slot)
// picks its instance's record in u_records, five texels from record
// a_slot + u_record_base: the rigid map from the mesh's coordinates to the
// cell's (relative to the cell's origin, as the eye uniforms take them), as
// its three rows, and the doors' planes that cut it, in the mesh's
// coordinates (keep >= 0; (0, 0, 0, 1) cuts nothing).
#if defined(OBJECT_CUTS)
layout(location = 6) in float a_slot;
uniform highp sampler2D u_records;
uniform int u_record_base;
#define RECORDS_PER_ROW 256
vec4 record_texel(int record, int k) {
    return texelFetch(u_records, ivec2(5 * (record % RECORDS_PER_ROW) + k, record / RECORDS_PER_ROW), 0);
}
#define CLIP_DISTANCE_COUNT 7
#else
#define CLIP_DISTANCE_COUNT 5
#endif
// VOLUMES: the draws of a cell with volume portals, and of their target
// rooms: the vertex in the coordinates of the cell's volumes (the cell's
// own, relative to its origin), for the fragment's inside test.
#if defined(VOLUMES)
uniform mat4 u_to_volume_space;
out vec3 v_volume_position;
#endif

// LIGHTS: the vertex in the coordinates of the room that lights it, less
// that room's cell origin (a cell's own vertices: as they are).
#if defined(LIGHTS)
uniform mat4 u_to_light_space;
out vec3 v_light_position;
#endif
// LIGHTS_CACHED: the vertex's place in the light cache's atlas, in cells
// (render/lights/light_cache.hpp).
#if defined(LIGHTS_CACHED)
layout(location = 7) in vec2 a_light_cell;
out vec2 v_light_cell;
#endif

out vec3 v_checker_position;
out vec3 v_normal;
out vec3 v_color;
out float v_checker;
#if defined(MATERIALS)
out vec2 v_uv;
out float v_alpha;
#endif

out float gl_ClipDistance[CLIP_DISTANCE_COUNT];

void main() {
#if defined(STEREO_SINGLE_EYE)
    int eye = u_single_eye;
#else
    int eye = gl_InstanceID & 1;
#endif
#if defined(OBJECT_CUTS)
    int record = int(a_slot) + u_record_base;
    vec4 model_row0 = record_texel(record, 0);
    vec4 model_row1 = record_texel(record, 1);
    vec4 model_row2 = record_texel(record, 2);
    vec4 mesh_position = vec4(a_position, 1.0);
    vec4 position = vec4(dot(model_row0, mesh_position), dot(model_row1, mesh_position),
                         dot(model_row2, mesh_position), 1.0);
#else
    vec4 position = vec4(a_position, 1.0);
#endif
    vec4 clip = u_view_proj[eye] * position;
    vec4 rect = u_eye_rect[eye];
    gl_ClipDistance[0] = clip.x - rect.x * clip.w;
    gl_ClipDistance[1] = rect.z * clip.w - clip.x;
    gl_ClipDistance[2] = clip.y - rect.y * clip.w;
    gl_ClipDistance[3] = rect.w * clip.w - clip.y;
    gl_ClipDistance[4] = dot(u_clip_plane[eye], position);
#if defined(OBJECT_CUTS)
    gl_ClipDistance[5] = dot(record_texel(record, 3), mesh_position);
    gl_ClipDistance[6] = dot(record_texel(record, 4), mesh_position);
#endif
#if defined(VOLUMES)
    v_volume_position = (u_to_volume_space * position).xyz;
#endif
#if defined(LIGHTS)
    v_light_position = (u_to_light_space * position).xyz;
#endif
#if defined(LIGHTS_CACHED)
    v_light_cell = a_light_cell;
#endif
#if defined(STEREO_VIEWPORT_INDEX)
    gl_ViewportIndex = eye;
#elif !defined(STEREO_SINGLE_EYE)
    // Left eye: x_ndc' = (x_ndc - 1) / 2; right eye: (x_ndc + 1) / 2.
    clip.x = 0.5 * (clip.x + (eye == 0 ? -clip.w : clip.w));
#endif
    gl_Position = clip;
    v_checker_position = a_position + u_checker_offset;
#if defined(OBJECT_CUTS)
    v_normal = vec3(dot(model_row0.xyz, a_normal), dot(model_row1.xyz, a_normal), dot(model_row2.xyz, a_normal));
#else
    v_normal = a_normal;
#endif
    v_color = a_color;
    v_checker = a_checker;
#if defined(MATERIALS)
    v_uv = a_uv;
    v_alpha = a_alpha;
#endif
}
