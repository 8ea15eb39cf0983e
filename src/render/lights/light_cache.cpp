// The light cache's charts, atlas and cells (light_cache.hpp).
#include "render/lights/light_cache.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <glm/geometric.hpp>

#include "render/lights/light_cache_cells.hpp"
#include "render/lights/light_cache_chart.hpp"

namespace impossible::render {
namespace {

constexpr int kRecordFloats = 24;  // an image's 6 vec4s

// Whether room c's images and batches can be cached at all.
bool cacheable_lights(const LightCacheInput& in, size_t c) {
    const lights::RoomLights& room = (*in.rooms)[c];
    if (room.images.size() < static_cast<size_t>(kLightCacheMinImages) ||
        room.images.size() > static_cast<size_t>(kLightCacheMaxImages))
        return false;
    // What each cell is tested against: every image's blockers, and its
    // legs' props' shadows where there are maps.
    size_t tests = 0;
    for (const lights::LightImage& image : room.images) {
        if (image.apertures.size() > 1 || (!image.apertures.empty() && !image.blockers.empty())) return false;
        tests += image.blockers.size();
        if (in.shadow_map_size > 0)
            for (const int leg_room : image.rooms) tests += (*in.objects)[static_cast<size_t>(leg_room)].objects.size();
    }
    if (tests > static_cast<size_t>(kLightCacheMaxTests)) return false;
    for (const scene::DrawBatch& b : (*in.cells)[c])
        if (b.texture >= 0 || b.alpha_cutoff >= 0.0f) return false;
    return true;
}

glm::dvec3 position_of(const LightCacheInput& in, std::uint32_t v) { return glm::dvec3((*in.vertices)[v].position); }

// Room c's triangles grouped by plane into `charts` (appended); false where
// one is not flat.
bool make_charts(const LightCacheInput& in, size_t c, std::vector<CacheChart>& charts) {
    std::map<std::array<long long, 4>, size_t> by_plane;
    const size_t first = charts.size();
    for (const scene::DrawBatch& b : (*in.cells)[c])
        for (std::uint32_t k = b.range.first; k + 2 < b.range.first + b.range.count; k += 3) {
            const std::array<std::uint32_t, 3> t = {(*in.indices)[k], (*in.indices)[k + 1], (*in.indices)[k + 2]};
            const glm::dvec3 a = position_of(in, t[0]);
            const glm::dvec3 n_raw = glm::cross(position_of(in, t[1]) - a, position_of(in, t[2]) - a);
            const double len = glm::length(n_raw);
            if (len < 1e-12) continue;  // draws nothing
            const glm::dvec3 n = n_raw / len;
            for (const std::uint32_t v : t)
                if (glm::dot(glm::dvec3((*in.vertices)[v].normal), n) < 0.9999) return false;
            const std::array<long long, 4> key = {std::llround(n.x * 1e5), std::llround(n.y * 1e5),
                                                  std::llround(n.z * 1e5), std::llround(glm::dot(n, a) * 1e5)};
            auto [at, added] = by_plane.emplace(key, charts.size());
            if (added) {
                CacheChart chart;
                chart.room = static_cast<int>(c);
                chart.normal = n;
                chart.offset = glm::dot(n, a);
                // u: square to n and to the axis n leans on least; v = n x u.
                const glm::dvec3 m = glm::abs(n);
                const glm::dvec3 axis = m.x <= m.y && m.x <= m.z ? glm::dvec3(1, 0, 0)
                                        : m.y <= m.z             ? glm::dvec3(0, 1, 0)
                                                                 : glm::dvec3(0, 0, 1);
                chart.u = glm::normalize(glm::cross(n, axis));
                chart.v = glm::cross(n, chart.u);
                charts.push_back(chart);
            }
            charts[at->second].triangles.push_back(t);
        }
    for (size_t i = first; i < charts.size(); ++i) {
        CacheChart& chart = charts[i];
        chart.lo = glm::dvec2(1e300);
        chart.hi = glm::dvec2(-1e300);
        for (const std::array<std::uint32_t, 3>& t : chart.triangles)
            for (const std::uint32_t v : t) {
                const glm::dvec2 q = chart.plane_point(position_of(in, v));
                chart.lo = glm::min(chart.lo, q);
                chart.hi = glm::max(chart.hi, q);
            }
    }
    return true;
}

// A twentieth of the nearest image's distance to the chart's rectangle.
double cell_side(const CacheChart& chart, const LightCacheInput& in) {
    double nearest = 1e300;
    const glm::dvec3 origin = (*in.origins)[static_cast<size_t>(chart.room)].origin;
    for (const lights::LightImage& image : (*in.rooms)[static_cast<size_t>(chart.room)].images) {
        const glm::dvec3 l = image.position - origin;
        const glm::dvec2 q = chart.plane_point(l);
        const glm::dvec2 off = glm::max(glm::max(chart.lo - q, q - chart.hi), glm::dvec2(0.0));
        const double h = glm::dot(chart.normal, l) - chart.offset;
        nearest = std::min(nearest, std::sqrt(glm::dot(off, off) + h * h));
    }
    return std::clamp(0.05 * nearest, kLightCacheMinCell, kLightCacheMaxCell);
}

// Each chart's cells (one of margin on every side), within the atlas's width
// and kLightCacheMaxCells in all.
void size_charts(std::vector<CacheChart>& charts) {
    double scale = 1.0;
    for (int attempt = 0; attempt < 64; ++attempt) {
        long total = 0;
        for (CacheChart& chart : charts) {
            const glm::dvec2 extent = chart.hi - chart.lo;
            chart.side = std::max(chart.side * scale, std::max(extent.x, extent.y) / (kLightCacheAtlasWidth - 3));
            chart.cells = glm::ivec2(glm::ceil(extent / chart.side)) + 2;
            total += static_cast<long>(chart.cells.x) * chart.cells.y;
        }
        if (total <= kLightCacheMaxCells) return;
        scale = 1.05 * std::sqrt(static_cast<double>(total) / kLightCacheMaxCells);
    }
}

// Shelves of charts, tallest first.
void pack_atlas(std::vector<CacheChart>& charts, LightCache& out) {
    long total = 0;
    int widest = 1;
    for (const CacheChart& chart : charts) {
        total += static_cast<long>(chart.cells.x) * chart.cells.y;
        widest = std::max(widest, chart.cells.x);
    }
    out.width = std::clamp(static_cast<int>(std::ceil(1.2 * std::sqrt(static_cast<double>(total)))), widest,
                           kLightCacheAtlasWidth);
    std::vector<size_t> order(charts.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return charts[a].cells.y > charts[b].cells.y; });
    int x = 0, y = 0, shelf = 0;
    for (const size_t i : order) {
        CacheChart& chart = charts[i];
        if (x + chart.cells.x > out.width) {
            y += shelf;
            x = 0;
            shelf = 0;
        }
        chart.at = {x, y};
        x += chart.cells.x;
        shelf = std::max(shelf, chart.cells.y);
    }
    out.height = std::max(1, y + shelf);
}

// The chart's cells: their images' bits, and the sum of the lit images at
// their corners.
void bake_chart(const LightCacheInput& in, const CacheChart& chart, LightCache& out) {
    const auto c = static_cast<size_t>(chart.room);
    const glm::dvec3 origin = (*in.origins)[c].origin;
    const lights::RoomLights& room = (*in.rooms)[c];
    const int nx = chart.cells.x, ny = chart.cells.y;
    std::vector<glm::dvec3> term(static_cast<size_t>((nx + 1) * (ny + 1)));
    for (size_t g = 0; g < room.images.size(); ++g) {
        const lights::LightImage& image = room.images[g];
        const ImageShadows shadows = image_shadows(image, *in.objects, origin, in.bounds[c], in.shadow_map_size);
        const float* record =
            in.packed_images->data() + static_cast<size_t>(in.first[c] + static_cast<int>(g)) * kRecordFloats;
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i)
                term[static_cast<size_t>(j * (nx + 1) + i)] = cached_term(record, chart.grid_point(i, j), chart.normal);
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                const std::array<glm::dvec3, 4> q = {chart.grid_point(i, j), chart.grid_point(i + 1, j),
                                                     chart.grid_point(i + 1, j + 1), chart.grid_point(i, j + 1)};
                const CellLight light = cell_light(image, shadows, origin, q);
                const int x = chart.at.x + i, y = chart.at.y + j;
                if (light == CellLight::Edge) {
                    out.edges[static_cast<size_t>(y * out.width + x)] |= 1u << g;
                } else if (light == CellLight::Lit) {
                    for (int b = 0; b < 2; ++b)
                        for (int a = 0; a < 2; ++a) {
                            const glm::dvec3& value = term[static_cast<size_t>((j + b) * (nx + 1) + i + a)];
                            float* texel =
                                &out.corners[4 * static_cast<size_t>((2 * y + b) * 2 * out.width + 2 * x + a)];
                            for (int k = 0; k < 3; ++k) texel[k] += static_cast<float>(value[k]);
                        }
                }
            }
    }
}

}  // namespace

LightCache build_light_cache(const LightCacheInput& in) {
    LightCache out;
    const size_t rooms = in.rooms->size();
    out.cached.assign(rooms, false);
    out.vertex_cells.assign(in.vertices->size(), glm::vec2(-1.0f));
    std::vector<CacheChart> charts;
    std::vector<int> vertex_chart(in.vertices->size(), -1);
    for (size_t c = 0; c < rooms; ++c) {
        if (c < in.excluded.size() && in.excluded[c]) continue;
        if (!cacheable_lights(in, c)) continue;
        const size_t first = charts.size();
        bool ok = make_charts(in, c, charts);
        // A vertex in two planes cannot have one place in the atlas.
        for (size_t i = first; ok && i < charts.size(); ++i)
            for (const std::array<std::uint32_t, 3>& t : charts[i].triangles)
                for (const std::uint32_t v : t) {
                    ok = ok && (vertex_chart[v] < 0 || vertex_chart[v] == static_cast<int>(i));
                    vertex_chart[v] = static_cast<int>(i);
                }
        if (!ok) {
            for (size_t i = first; i < charts.size(); ++i)
                for (const std::array<std::uint32_t, 3>& t : charts[i].triangles)
                    for (const std::uint32_t v : t) vertex_chart[v] = -1;
            charts.resize(first);
            continue;
        }
        out.cached[c] = true;
        for (size_t i = first; i < charts.size(); ++i) charts[i].side = cell_side(charts[i], in);
    }
    size_charts(charts);
    pack_atlas(charts, out);
    long total = 0;
    for (const CacheChart& chart : charts) total += static_cast<long>(chart.cells.x) * chart.cells.y;
    if (total > kLightCacheMaxCells || out.height > kLightCacheAtlasMaxHeight) {
        // Too many charts to fit (each has at least 3 x 3 cells): no cache.
        charts.clear();
        out.cached.assign(rooms, false);
        vertex_chart.assign(vertex_chart.size(), -1);
        out.width = out.height = 1;
    }
    out.corners.assign(4 * static_cast<size_t>(4 * out.width) * out.height, 0.0f);
    out.edges.assign(static_cast<size_t>(out.width) * out.height, 0u);
    for (size_t v = 0; v < vertex_chart.size(); ++v)
        if (vertex_chart[v] >= 0)
            out.vertex_cells[v] = glm::vec2(charts[static_cast<size_t>(vertex_chart[v])].atlas_point(
                position_of(in, static_cast<std::uint32_t>(v))));
    for (const CacheChart& chart : charts) {
        bake_chart(in, chart, out);
        out.cell_count += static_cast<long>(chart.cells.x) * chart.cells.y;
    }
    for (const std::uint32_t bits : out.edges) out.edge_cells += bits != 0u ? 1 : 0;
    return out;
}

}  // namespace impossible::render
