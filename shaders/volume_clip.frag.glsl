// The volume test both scene fragment shaders share (scene.frag.glsl,
// portal_texture.frag.glsl): render/programs/scene_program.cpp puts it before each
// of them. Only the VOLUMES variants compile it.
#if defined(VOLUMES)
// The cell's volume portals: four vec4s each in one buffer of every room's
// (render::RendererData::volume_boxes), from u_volume_first: the box's centre
// and its three axes divided by its half extents, so that a point is inside
// when |dot(p - centre, axis)| <= 1 for all three.
in vec3 v_volume_position;
#if defined(WEBGL)
// WebGL 2 has no storage buffers: a uniform block (gl/webgl.hpp's size).
layout(std140, binding = 3) uniform VolumeBoxes {
    vec4 volume_boxes[1024];
};
#else
layout(std430, binding = 3) readonly buffer VolumeBoxes {
    vec4 volume_boxes[];
};
#endif
uniform int u_volume_first;
uniform int u_volume_count;
// -1: the cell's own surfaces, hidden inside every volume; k >= 0: a volume's
// target room, shown only inside volume k.
uniform int u_volume_inside;
uniform vec3 u_volume_tint;  // multiplies what is seen inside the volume

bool in_volume(int k) {
    int b = 4 * (u_volume_first + k);
    vec3 d = v_volume_position - volume_boxes[b].xyz;
    vec3 q = abs(vec3(dot(d, volume_boxes[b + 1].xyz), dot(d, volume_boxes[b + 2].xyz), dot(d, volume_boxes[b + 3].xyz)));
    return max(q.x, max(q.y, q.z)) <= 1.0 + VOLUME_TOLERANCE;
}

void clip_to_volumes() {
    if (u_volume_inside >= 0) {
        if (!in_volume(u_volume_inside)) discard;
        return;
    }
    for (int k = 0; k < u_volume_count; ++k)
        if (in_volume(k)) discard;
}
#endif
