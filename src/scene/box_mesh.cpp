#include "scene/box_mesh.hpp"

#include <algorithm>
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

namespace {

// One corner of a glTF triangle placed in the layout: colour = the material's
// factor times COLOR_0, alpha likewise; `side` -1 reverses the normal (the
// back of a double-sided triangle).
std::uint32_t model_vertex(MeshWriter& out, const layout::GltfProp& prop, const assets::ModelTriangle& t,
                           const assets::Material& material, std::size_t k, double side) {
    const glm::dvec3 p = layout::place_model_point(prop, t.position[k]);
    glm::dvec3 n = layout::place_model_normal(prop, t.normal[k]);
    const double length = glm::length(n);
    if (length > 0.0 && std::isfinite(length)) n /= length;  // keep it unit after float rounding
    const glm::dvec4& c = t.vertex_color[k];
    return out.vertex(out.local(p), side * n, t.color * glm::dvec3(c), 0.0, t.uv[k], material.base_color.a * c.a);
}

}  // namespace

void append_gltf_prop(MeshWriter& out, const layout::GltfProp& prop, std::vector<DrawBatch>& batches) {
    const assets::Material kDefault;
    const auto material_of = [&](int m) -> const assets::Material& {
        return m < 0 ? kDefault : prop.materials[static_cast<std::size_t>(m)];
    };
    // Each used material's draw state, made on first use (so that only used
    // textures are uploaded).
    std::vector<DrawBatch> state_of(prop.materials.size() + 1);
    std::vector<bool> known(prop.materials.size() + 1, false);
    std::vector<DrawBatch> states;  // distinct, in order of first use
    const auto state = [&](int m) -> const DrawBatch& {
        const auto at = static_cast<std::size_t>(m + 1);
        if (!known[at]) {
            const assets::Material& mat = material_of(m);
            DrawBatch b;
            if (mat.texture >= 0) {
                const assets::Texture& tex = prop.textures[static_cast<std::size_t>(mat.texture)];
                b.texture = out.texture(tex.image, tex.sampler);
            }
            if (mat.alpha_mode == assets::AlphaMode::Mask) b.alpha_cutoff = static_cast<float>(mat.alpha_cutoff);
            state_of[at] = b;
            known[at] = true;
            if (std::none_of(states.begin(), states.end(), [&](const DrawBatch& s) { return s.same_state(b); }))
                states.push_back(b);
        }
        return state_of[at];
    };
    for (const assets::ModelTriangle& t : prop.triangles) state(t.material);

    // Triangles grouped by state, in their order within each (a model whose
    // materials all draw alike keeps its order, and is one batch).
    for (const DrawBatch& s : states) {
        const std::uint32_t first = out.index_count();
        for (const assets::ModelTriangle& t : prop.triangles) {
            if (!state(t.material).same_state(s)) continue;
            const assets::Material& mat = material_of(t.material);
            std::uint32_t ids[3];
            for (std::size_t k = 0; k < 3; ++k) ids[k] = model_vertex(out, prop, t, mat, k, 1.0);
            out.triangle(ids[0], ids[1], ids[2]);
            if (mat.double_sided) {  // the back: reversed winding and normals
                for (std::size_t k = 0; k < 3; ++k) ids[k] = model_vertex(out, prop, t, mat, k, -1.0);
                out.triangle(ids[0], ids[2], ids[1]);
            }
        }
        DrawBatch b = s;
        b.range = out.range_since(first);
        add_batch(batches, b);
    }
}

}  // namespace impossible::scene
