// Helpers for tests that render: a context per backend, layouts from text,
// and one-call frames.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "gl/context.hpp"
#include "layout/layout.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace impossible::testing {

inline layout::Layout layout_from_text(const std::string& text) {
    layout::LoadResult r = layout::load_layout_text(text, "<test>", ".");
    std::string all;
    for (const auto& d : r.errors) all += d.str() + "\n";
    EXPECT_TRUE(r.errors.empty()) << all;
    return r.layout ? *r.layout : layout::Layout{};
}

inline layout::Layout layout_from_file(const std::string& path) {
    layout::LoadResult r = layout::load_layout_file(path);
    std::string all;
    for (const auto& d : r.errors) all += d.str() + "\n";
    EXPECT_TRUE(r.errors.empty()) << all;
    return r.layout ? *r.layout : layout::Layout{};
}

// One of the example layouts in layouts/, by file name.
inline layout::Layout example_layout(const char* name) {
    return layout_from_file(std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/" + name);
}

// vr_study.json (six doors) with a grid of n small boxes of three heights on
// every room's floor (the culling and box-face tests).
inline layout::Layout crowded_vr_study(int n) {
    layout::Layout l = example_layout("vr_study.json");
    const int side = static_cast<int>(std::ceil(std::sqrt(double(n))));
    for (layout::Room& room : l.rooms) {
        const glm::dvec3 extent = room.max - room.min;
        const double size = 0.4 * std::min(extent.x, extent.z) / side;
        for (int i = 0; i < n; ++i) {
            layout::BoxProp box;
            const double x = room.min.x + (i % side + 0.5) * extent.x / side;
            const double z = room.min.z + (i / side + 0.5) * extent.z / side;
            box.min = {x - 0.5 * size, room.min.y, z - 0.5 * size};
            box.max = {x + 0.5 * size, room.min.y + (1 + i % 3) * size, z + 0.5 * size};
            box.color = {0.3 + 0.1 * (i % 5), 0.5, 0.3};
            room.props.push_back(box);
        }
    }
    return l;
}

// Renders one frame in a fresh context of the given backend.
inline image::Image render_once(gl::Backend backend, const layout::Layout& layout, const render::FrameDesc& frame,
                                render::FrameStats* stats = nullptr) {
    Result<gl::Context> context = gl::create_context(backend);
    EXPECT_TRUE(context.has_value()) << context.error();
    if (!context) return {};
    Result<render::Renderer> renderer = render::Renderer::create(context->state(), scene::build_scene(layout));
    EXPECT_TRUE(renderer.has_value()) << renderer.error();
    if (!renderer) return {};
    Result<render::RenderedFrame> result = renderer->render(frame);
    EXPECT_TRUE(result.has_value()) << result.error();
    if (!result) return {};
    if (stats) *stats = result->stats;
    return result->image;
}

// Number of pixels whose colour differs by more than `tolerance` in a channel.
inline int count_colour_differences(const image::Image& a, const image::Image& b, int tolerance = 0) {
    if (a.width != b.width || a.height != b.height) return -1;
    int n = 0;
    for (size_t i = 0; i < a.rgb.size(); i += 3)
        for (int c = 0; c < 3; ++c)
            if (std::abs(int(a.rgb[i + c]) - int(b.rgb[i + c])) > tolerance) {
                ++n;
                break;
            }
    return n;
}

inline int count_id_differences(const image::Image& a, const image::Image& b) {
    if (a.width != b.width || a.height != b.height) return -1;
    int n = 0;
    for (size_t i = 0; i < a.ids.size(); ++i) n += a.ids[i] != b.ids[i];
    return n;
}

// The shading model written out by hand: base · (0.45 + 0.55 · max(0, n·L)),
// L the unit vector along (0.3, 0.9, 0.4), as 8-bit values.
inline std::array<int, 3> expected_colour(std::array<double, 3> base, std::array<double, 3> n) {
    const double len = std::sqrt(0.3 * 0.3 + 0.9 * 0.9 + 0.4 * 0.4);
    const double ndotl = (n[0] * 0.3 + n[1] * 0.9 + n[2] * 0.4) / len;
    const double k = 0.45 + 0.55 * std::max(0.0, ndotl);
    return {int(std::lround(base[0] * k * 255)), int(std::lround(base[1] * k * 255)),
            int(std::lround(base[2] * k * 255))};
}

inline const std::uint8_t* pixel(const image::Image& image, int x, int y) {
    return &image.rgb[(static_cast<size_t>(y) * image.width + x) * 3];
}
inline std::uint8_t id_at(const image::Image& image, int x, int y) {
    return image.ids[static_cast<size_t>(y) * image.width + x];
}

inline const char* kSingleRoom = R"({
  "format": "impossible-layout", "version": 1,
  "start": { "room": "box", "position": [0, 1.5, 0] },
  "rooms": [ { "id": "box", "min": [-2, 0, -3], "max": [2, 3, 3],
               "color": [0.6, 0.6, 0.6],
               "face_colors": { "floor": [0.2, 0.4, 0.8], "-z": [0.9, 0.3, 0.1], "ceiling": [1, 1, 1] },
               "props": [ { "box": { "min": [-0.5, 0, -2.0], "max": [0.5, 1.0, -1.0] }, "color": [0.1, 0.8, 0.2] } ] } ]
})";

}  // namespace impossible::testing
