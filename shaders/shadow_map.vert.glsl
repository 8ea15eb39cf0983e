// A prop drawn into one face of a light image's cube shadow map
// (render/lights/shadow_maps.hpp): positions relative to the image's position L',
// in the lit room's coordinates, clipped to the leg's slab and the object's
// door cuts.
layout(location = 0) in vec3 a_position;
layout(location = 4) in vec2 a_uv;
layout(location = 5) in float a_alpha;

uniform mat4 u_model;      // the mesh's vertex coordinates -> L'-relative
uniform mat4 u_face_proj;  // the face's projection times its view
// Keep dot(plane, (p, 1)) >= 0, p L'-relative: the slab's two planes, then
// the object's two cuts; (0, 0, 0, 1) keeps everything.
uniform vec4 u_planes[4];

out vec3 v_relative;
out vec2 v_uv;
out float v_alpha;
out float gl_ClipDistance[4];

void main() {
    vec4 p = u_model * vec4(a_position, 1.0);
    v_relative = p.xyz;
    v_uv = a_uv;
    v_alpha = a_alpha;
    for (int i = 0; i < 4; ++i) gl_ClipDistance[i] = dot(u_planes[i], p);
    gl_Position = u_face_proj * p;
}
