#include "scene/box_mesh.hpp"

#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>

namespace impossible::scene {

void append_box_prop(MeshWriter& out, const layout::BoxProp& box) {
    const glm::vec3 lo(out.local(box.min)), hi(out.local(box.max));
    for (int axis = 0; axis < 3; ++axis) {
        for (const bool positive : {false, true}) {
            const PlaneAxes in = plane_axes(axis, positive);  // counter-clockwise seen from outside
            const float plane = positive ? hi[axis] : lo[axis];
            glm::dvec3 normal(0.0);
            normal[axis] = positive ? 1.0 : -1.0;
            const auto corner = [&](float a, float b) {
                return out.vertex(plane_point(axis, plane, in, a, b), normal, box.color, 0.0);
            };
            const std::uint32_t v00 = corner(lo[in.a], lo[in.b]);
            const std::uint32_t v10 = corner(hi[in.a], lo[in.b]);
            const std::uint32_t v11 = corner(hi[in.a], hi[in.b]);
            const std::uint32_t v01 = corner(lo[in.a], hi[in.b]);
            out.triangle(v00, v10, v11);
            out.triangle(v00, v11, v01);
        }
    }
}

void append_gltf_prop(MeshWriter& out, const layout::GltfProp& prop) {
    for (const layout::ModelTriangle& t : prop.triangles) {
        std::uint32_t ids[3];
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 p =
                layout::place_model_point(prop, t.position[static_cast<std::size_t>(k)]);
            glm::dvec3 n = layout::place_model_normal(prop, t.normal[static_cast<std::size_t>(k)]);
            const double length = glm::length(n);
            if (length > 0.0 && std::isfinite(length))
                n /= length;  // keep it unit after float rounding
            ids[k] = out.vertex(out.local(p), n, t.color, 0.0);
        }
        out.triangle(ids[0], ids[1], ids[2]);
    }
}

}  // namespace impossible::scene
