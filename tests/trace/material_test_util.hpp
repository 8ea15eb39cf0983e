// Textured props for the tracer's material tests (tracer_material_test.cpp,
// tracer_alpha_test.cpp): a 2 × 2 image whose quadrants differ in every
// channel, and a quad that shows it whole.
#pragma once

#include <array>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <utility>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "trace/trace_test_util.hpp"

namespace impossible::trace::test {

using glm::dvec2;
using glm::dvec4;

inline std::shared_ptr<const image::Pixels> image_of(int width, int height, std::initializer_list<std::uint8_t> bytes) {
    auto image = std::make_shared<image::Pixels>();
    image->width = width;
    image->height = height;
    image->data = bytes;
    return image;
}

// 2 × 2, all channels different from quadrant to quadrant: top-left,
// top-right, bottom-left, bottom-right (the last with alpha `last_alpha`).
inline std::shared_ptr<const image::Pixels> quadrants(std::uint8_t top_right_alpha = 255) {
    return image_of(2, 2, {255, 128, 64, 255, 64, 255, 128, top_right_alpha, 128, 64, 255, 255, 204, 204, 51, 255});
}
// The texel of quadrants() at column i, row j, as the tracer reads bytes.
inline dvec4 quadrant(int i, int j, std::uint8_t top_right_alpha = 255) {
    const std::uint8_t q[4][4] = {
        {255, 128, 64, 255}, {64, 255, 128, top_right_alpha}, {128, 64, 255, 255}, {204, 204, 51, 255}};
    const std::uint8_t* p = q[2 * j + i];
    return dvec4(p[0], p[1], p[2], p[3]) / 255.0;
}

// A quad x ∈ [-1, 1], y ∈ [0.5, 2.5] in the plane z = -1, facing +z (two
// triangles, counter-clockwise seen from +z), with material `material`,
// uv (0, 0) at its top-left corner (s = (x + 1) / 2, t = (2.5 - y) / 2),
// COLOR_0 `vertex` and the vertex normal `normal`.
inline void add_quad(layout::GltfProp& model, int material, dvec4 vertex = dvec4(1.0), dvec3 normal = {0, 0, 1}) {
    auto corner = [](double x, double y) { return dvec3(x, y, -1.0); };
    auto uv = [](const dvec3& p) { return dvec2((p.x + 1.0) / 2.0, (2.5 - p.y) / 2.0); };
    const dvec3 a = corner(-1, 0.5), b = corner(1, 0.5), c = corner(1, 2.5), d = corner(-1, 2.5);
    for (const auto& tri : {std::array<dvec3, 3>{a, b, c}, std::array<dvec3, 3>{a, c, d}}) {
        assets::ModelTriangle t;
        t.position = tri;
        t.normal = {normal, normal, normal};
        t.color = material >= 0 ? dvec3(model.materials[material].base_color) : dvec3(0.8);
        t.vertex_color = {vertex, vertex, vertex};
        t.uv = {uv(tri[0]), uv(tri[1]), uv(tri[2])};
        t.material = material;
        model.triangles.push_back(t);
    }
}

inline assets::Texture texture(std::shared_ptr<const image::Pixels> image, int filter) {
    assets::Texture t;
    t.image = std::move(image);
    t.sampler.mag_filter = filter;
    return t;
}

}  // namespace impossible::trace::test
