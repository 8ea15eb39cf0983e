// The light cache's build (render/lights/light_cache.hpp), without a GL
// context: which rooms it caches, where each vertex lies in the atlas, and
// that the cached sum plus the images a cell's bits name is the exact sum
// at random points of the cached surfaces; and that a cell said to be lit or
// dark for an image is so at every point of it.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <utility>
#include <variant>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "common/segment_box.hpp"
#include "gl_fixture.hpp"
#include "lights/light_images.hpp"
#include "links/portal_links.hpp"
#include "render/lights/light_buffers.hpp"
#include "render/lights/light_cache.hpp"
#include "render/lights/light_cache_cells.hpp"
#include "scene/scene.hpp"

namespace impossible {
namespace {

// The lamp hall with 8 point lights under each room's ceiling.
layout::Layout lamp_hall_with_8() {
    layout::Layout l = testing::example_layout("lamp_hall.json");
    for (layout::Room& room : l.rooms) {
        room.lights.clear();
        for (int k = 0; k < 8; ++k) {
            layout::Light light;
            light.position = {room.min.x + (k % 3 + 0.5) / 3 * (room.max.x - room.min.x), room.max.y - 0.3,
                              room.min.z + (k / 3 + 0.5) / 3 * (room.max.z - room.min.z)};
            light.color = {1.0, 0.95, 0.9};
            light.intensity = 0.5;
            room.lights.push_back(light);
        }
    }
    return l;
}

struct Built {
    layout::Layout layout;
    scene::Scene scene;
    std::vector<lights::RoomLights> rooms;
    render::PackedLights packed;
    std::vector<int> first;
    render::LightCache cache;
};

Built build(const layout::Layout& l, int map_size) {
    Built b{l, scene::build_scene(l), {}, {}, {}, {}};
    b.rooms = lights::light_images(l, links::link_portals(l), l.light_depth);
    b.packed = render::pack_light_images(b.rooms, l, b.scene.origins);
    int first = 0;
    for (const lights::RoomLights& r : b.rooms) {
        b.first.push_back(first);
        first += static_cast<int>(r.images.size());
    }
    render::LightCacheInput in{.vertices = &b.scene.vertices,
                               .indices = &b.scene.indices,
                               .cells = &b.scene.batches,
                               .objects = &b.scene.objects,
                               .origins = &b.scene.origins,
                               .rooms = &b.rooms,
                               .packed_images = &b.packed.images,
                               .first = b.first,
                               .excluded = {},
                               .bounds = {},
                               .shadow_map_size = map_size};
    for (const layout::Room& room : l.rooms) in.bounds.emplace_back(room.min, room.max);
    b.cache = render::build_light_cache(in);
    return b;
}

const float* record(const Built& b, size_t room, size_t g) {
    return b.packed.images.data() + static_cast<size_t>(b.first[room] + static_cast<int>(g)) * 24;
}

TEST(LightCacheBuild, TheCachedSumAndTheCellsImagesAreTheExactSum) {
    // Without prop shadows (map size 0): the exact sum is the images whose
    // segments pass their apertures and blockers (lights::segment_passes).
    const Built b = build(lamp_hall_with_8(), 0);
    ASSERT_EQ(b.cache.cached.size(), 2u);
    EXPECT_TRUE(b.cache.cached[0]) << "the hall";
    EXPECT_TRUE(b.cache.cached[1]) << "the annex (its own lights meet the door standing in it)";
    EXPECT_GT(b.cache.edge_cells, 0);
    EXPECT_LT(b.cache.edge_cells, b.cache.cell_count / 2);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int checked = 0;
    for (size_t c = 0; c < b.rooms.size(); ++c)
        for (const scene::DrawBatch& batch : b.scene.batches[c])
            for (std::uint32_t k = batch.range.first; k + 2 < batch.range.first + batch.range.count; k += 3) {
                const std::uint32_t t[3] = {b.scene.indices[k], b.scene.indices[k + 1], b.scene.indices[k + 2]};
                for (const std::uint32_t v : t) {
                    const glm::vec2 at = b.cache.vertex_cells[v];
                    ASSERT_GE(at.x, 0.5f);
                    ASSERT_GE(at.y, 0.5f);
                    ASSERT_LE(at.x, static_cast<float>(b.cache.width) - 0.5f);
                    ASSERT_LE(at.y, static_cast<float>(b.cache.height) - 0.5f);
                }
                for (int s = 0; s < 6; ++s) {
                    double u = unit(rng), w = unit(rng);
                    if (u + w > 1.0) u = 1.0 - u, w = 1.0 - w;
                    const double weights[3] = {1.0 - u - w, u, w};
                    glm::dvec3 p(0.0);
                    glm::dvec2 at(0.0);
                    for (int i = 0; i < 3; ++i) {
                        p += weights[i] * glm::dvec3(b.scene.vertices[t[i]].position);
                        at += weights[i] * glm::dvec2(b.cache.vertex_cells[t[i]]);
                    }
                    const glm::dvec3 n(b.scene.vertices[t[0]].normal);
                    const glm::ivec2 cell(glm::floor(at));
                    const glm::dvec2 f = at - glm::dvec2(cell);
                    const auto corner = [&](int i, int j) {
                        const float* texel =
                            &b.cache.corners[4 * static_cast<size_t>((2 * cell.y + j) * 2 * b.cache.width + 2 * cell.x +
                                                                     i)];
                        return glm::dvec3(texel[0], texel[1], texel[2]);
                    };
                    glm::dvec3 cached = glm::mix(glm::mix(corner(0, 0), corner(1, 0), f.x),
                                                 glm::mix(corner(0, 1), corner(1, 1), f.x), f.y);
                    const std::uint32_t bits = b.cache.edges[static_cast<size_t>(cell.y * b.cache.width + cell.x)];
                    glm::dvec3 exact(0.0);
                    const glm::dvec3 layout_p = p + b.scene.origins[c].origin;
                    for (size_t g = 0; g < b.rooms[c].images.size(); ++g) {
                        if (!lights::segment_passes(b.rooms[c].images[g], layout_p)) continue;
                        const glm::dvec3 term = render::cached_term(record(b, c, g), p, n);
                        exact += term;
                        if ((bits >> g) & 1u) cached += term;
                    }
                    const double scale = std::max({exact.x, exact.y, exact.z, 0.05});
                    EXPECT_NEAR(cached.x, exact.x, 0.01 * scale)
                        << "room " << c << " at " << p.x << ", " << p.y << ", " << p.z;
                    ++checked;
                }
            }
    EXPECT_GT(checked, 100);
}

TEST(LightCacheBuild, ARoomOfManyPropsIsDrawnExactly) {
    // 8 lights a room and 70 boxes in the hall: its 8 own lights alone
    // have 8 x 71 shadows for its cells to be tested against, more than
    // kLightCacheMaxTests. Without prop shadows, the same room is cached.
    layout::Layout l = lamp_hall_with_8();
    for (int k = 0; k < 70; ++k) {
        layout::BoxProp box;
        box.min = {-1.9 + 0.03 * k, 0.0, 1.7};
        box.max = box.min + glm::dvec3(0.02, 0.1, 0.02);
        l.rooms[0].props.emplace_back(box);
    }
    EXPECT_FALSE(build(l, 512).cache.cached[0]);
    EXPECT_TRUE(build(l, 0).cache.cached[0]);
}

TEST(LightCacheBuild, AHugeRoomsCellsGrowToFitTheAtlas) {
    // A hall of 1 km x 1 km: at the largest cell side its floor alone would
    // need 16 million cells; they grow until the atlas holds at most
    // kLightCacheMaxCells.
    layout::Layout l = lamp_hall_with_8();
    l.rooms[0].min = {-1000.0, 0.0, -500.0};
    l.rooms[0].max = {0.6, 3.0, 500.0};
    const Built b = build(l, 0);
    ASSERT_TRUE(b.cache.cached[0]);
    EXPECT_LE(b.cache.cell_count, render::kLightCacheMaxCells);
    EXPECT_LE(static_cast<long>(b.cache.width) * b.cache.height, 2 * render::kLightCacheMaxCells);
}

TEST(LightCacheBuild, ACellLitOrDarkForAnImageIsSoAtEveryPoint) {
    // Random squares on the hall's floor and walls, random points in them:
    // where cell_light says Lit, the point's segment to the image passes its
    // aperture and meets no prop; where it says Dark, it does not reach.
    const Built b = build(lamp_hall_with_8(), 512);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int lit = 0, dark = 0, edge = 0;
    for (size_t c = 0; c < 2; ++c) {
        const layout::Room& room = b.layout.rooms[c];
        const glm::dvec3 origin = b.scene.origins[c].origin;
        for (size_t g = 0; g < b.rooms[c].images.size(); ++g) {
            const lights::LightImage& image = b.rooms[c].images[g];
            const render::ImageShadows shadows =
                render::image_shadows(image, b.scene.objects, origin, {room.min, room.max}, 512);
            for (int s = 0; s < 150; ++s) {
                const double side = 0.01 + 0.2 * unit(rng);
                // On the floor (y = 0) or the wall x = min.
                const bool floor = s % 2 == 0;
                const glm::dvec3 a = floor ? glm::dvec3(glm::mix(room.min.x, room.max.x - side, unit(rng)), 0.0,
                                                        glm::mix(room.min.z, room.max.z - side, unit(rng)))
                                           : glm::dvec3(room.min.x, glm::mix(0.0, room.max.y - side, unit(rng)),
                                                        glm::mix(room.min.z, room.max.z - side, unit(rng)));
                const glm::dvec3 du = floor ? glm::dvec3(side, 0, 0) : glm::dvec3(0, side, 0);
                const glm::dvec3 dv(0, 0, side);
                const std::array<glm::dvec3, 4> q = {a - origin, a + du - origin, a + du + dv - origin,
                                                     a + dv - origin};
                const render::CellLight light = render::cell_light(image, shadows, origin, q);
                if (light == render::CellLight::Edge) {
                    ++edge;
                    continue;
                }
                (light == render::CellLight::Lit ? lit : dark) += 1;
                for (int k = 0; k < 10; ++k) {
                    const glm::dvec3 p = a + unit(rng) * du + unit(rng) * dv;
                    bool reaches = lights::segment_passes(image, p);
                    // The props of the image's legs, in this room's coordinates.
                    for (size_t leg = 0; leg < image.rooms.size() && reaches; ++leg) {
                        const glm::dmat4& from_c = image.to_room[leg];  // C -> the leg's room
                        for (const layout::Prop& prop : b.layout.rooms[static_cast<size_t>(image.rooms[leg])].props) {
                            const layout::BoxProp* box = std::get_if<layout::BoxProp>(&prop);
                            if (!box) continue;
                            const glm::dvec3 pl(from_c * glm::dvec4(p, 1.0)),
                                ll(from_c * glm::dvec4(image.position, 1.0));
                            if (testing::segment_meets_box(pl, ll, box->min, box->max)) reaches = false;
                        }
                    }
                    EXPECT_EQ(reaches, light == render::CellLight::Lit)
                        << "room " << c << ", image " << g << ", at " << p.x << ", " << p.y << ", " << p.z;
                }
            }
        }
    }
    std::printf("  cells: %d lit, %d dark, %d edge\n", lit, dark, edge);
    EXPECT_GT(lit, 100);
    EXPECT_GT(dark, 20);
}

}  // namespace
}  // namespace impossible
