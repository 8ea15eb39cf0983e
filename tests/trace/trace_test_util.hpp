// Layouts built in code and hand-written expectations for the tracer tests.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "common/layouts.hpp"
#include "layout/layout.hpp"
#include "shading/shading.hpp"
#include "trace/tracer.hpp"

namespace impossible::trace::test {

using glm::dvec3;

using impossible::test::add_pair;
using impossible::test::make_mirror;
using impossible::test::make_portal;
using impossible::test::make_room;
using impossible::test::make_window;

// Positions the tracer computes are exact to this (metres).
inline constexpr double kTol = 1e-12;
inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline const dvec3& kFill = shading::kPortalFillColor;
inline const dvec3 kRed{1, 0, 0}, kGreen{0, 1, 0}, kBlue{0, 0, 1};

inline void expect_point(const dvec3& got, const dvec3& want, double tol = kTol) {
    EXPECT_NEAR(got.x, want.x, tol);
    EXPECT_NEAR(got.y, want.y, tol);
    EXPECT_NEAR(got.z, want.z, tol);
}

// The scan's and the tree's nearest hit on one ray (of boxes or of
// triangles) agree: the same index, and the same t and normal where there is
// a hit. Counts the ray and the hit in `tally`.
template <class Hit, class Tally>
void expect_same_nearest(const Hit& scan, const Hit& tree, const dvec3& origin, const dvec3& dir, Tally& tally) {
    ++tally.rays;
    ASSERT_EQ(scan.index, tree.index) << "origin " << origin.x << ", " << origin.y << ", " << origin.z << " dir "
                                      << dir.x << ", " << dir.y << ", " << dir.z;
    ASSERT_EQ(scan.hit.has_value(), tree.hit.has_value());
    if (!scan.hit) return;
    ++tally.hits;
    ASSERT_EQ(scan.hit->t, tree.hit->t);
    ASSERT_EQ(scan.hit->normal, tree.hit->normal);
}

// The frames of `a` and `b` (a scene with its triangle trees and a copy
// without them, which the tracer scans) are the same. Returns a's frame.
inline image::Image expect_same_frames(const Scene& a, const Scene& b, const TraceDesc& desc) {
    image::Image first = trace_frame(a, desc).value();
    const image::Image second = trace_frame(b, desc).value();
    EXPECT_EQ(first.rgb, second.rgb);
    EXPECT_EQ(first.ids, second.ids);
    return first;
}

// The built-in default layout, loaded from layouts/.
inline layout::Layout load_default() {
    const layout::LoadResult loaded = layout::load_layout_file(IMPOSSIBLE_SOURCE_DIR "/layouts/default.json");
    EXPECT_TRUE(loaded.errors.empty());
    return loaded.layout.value();
}

// One closed room, the head in it.
inline layout::Layout one_room(dvec3 min = {-2, 0, -2}, dvec3 max = {2, 3, 2}) {
    layout::Layout l;
    l.source = "<test>";
    l.rooms.push_back(make_room("room", min, max));
    l.start.room = 0;
    return l;
}

inline dvec3 face_color(const layout::Room& room, layout::Face face) { return room.face_color[static_cast<int>(face)]; }

// The shading model of scene/shading.hpp written out again by hand (with its
// constants, which may be tuned), so that a test does not merely repeat the
// tracer's own call: the test names the surface's base colour, normal and
// checker square itself.
inline dvec3 shade_by_hand(dvec3 base, dvec3 normal, bool dark) {
    const double lambert = std::max(0.0, glm::dot(normal, shading::kLightDir));
    return base * ((shading::kAmbient + shading::kDiffuse * lambert) * (dark ? shading::kCheckerDark : 1.0));
}

inline std::array<std::uint8_t, 3> bytes_of(dvec3 c) {
    std::array<std::uint8_t, 3> out{};
    for (int k = 0; k < 3; ++k) out[k] = static_cast<std::uint8_t>(std::lround(std::clamp(c[k], 0.0, 1.0) * 255.0));
    return out;
}

inline std::array<std::uint8_t, 3> pixel_rgb(const image::Image& image, int x, int y) {
    const size_t at = 3 * (static_cast<size_t>(y) * image.width + x);
    return {image.rgb[at], image.rgb[at + 1], image.rgb[at + 2]};
}

inline int pixel_id(const image::Image& image, int x, int y) {
    return image.ids[static_cast<size_t>(y) * image.width + x];
}

// Counts the pixels of the id map equal to `id`.
inline long count_id(const image::Image& image, int id) {
    return static_cast<long>(std::count(image.ids.begin(), image.ids.end(), static_cast<std::uint8_t>(id)));
}

}  // namespace impossible::trace::test
