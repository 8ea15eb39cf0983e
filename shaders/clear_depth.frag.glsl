// The full-target triangle's colour and id: the background and id 0, for
// clearing a window's pixels between its two views. Clearing depth only and
// tinting mask or ignore them (see render/portals/passes.hpp).
uniform vec4 u_color;

layout(location = 0) out vec4 o_color;
layout(location = 1) out uint o_id;

void main() {
    o_color = u_color;
    o_id = 0u;
}
