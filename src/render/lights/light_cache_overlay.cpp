// The light cache's overlay (light_cache_overlay.hpp).
#include "render/lights/light_cache_overlay.hpp"

#include <algorithm>

namespace impossible::render {
namespace {

// Rectangles of cells [x0, x1) x [y0, y1), in the chart's cells, covering
// its cells with edge bits: runs along each row, joined with the same run
// of the row before.
std::vector<glm::ivec4> edge_rects(const CacheChart& chart, const LightCache& out) {
    std::vector<glm::ivec4> rects;
    std::vector<size_t> open;  // rects that end at the row before
    for (int j = 0; j < chart.cells.y; ++j) {
        std::vector<size_t> now;
        for (int i = 0; i < chart.cells.x;) {
            const auto edge = [&](int x) {
                return out.edges[static_cast<size_t>((chart.at.y + j) * out.width + chart.at.x + x)] != 0u;
            };
            if (!edge(i)) {
                ++i;
                continue;
            }
            int end = i;
            while (end < chart.cells.x && edge(end)) ++end;
            const auto same = std::find_if(open.begin(), open.end(), [&](size_t r) {
                return rects[r].x == i && rects[r].z == end;
            });
            if (same != open.end()) {
                rects[*same].w = j + 1;
                now.push_back(*same);
            } else {
                rects.push_back({i, j, end, j + 1});
                now.push_back(rects.size() - 1);
            }
            i = end;
        }
        open = std::move(now);
    }
    return rects;
}

}  // namespace

void add_overlays(const LightCacheInput& in, const std::vector<CacheChart>& charts, LightCache& out) {
    const size_t rooms = out.cached.size();
    out.overlay_first.assign(rooms + 1, 0);
    out.overlay_pieces.assign(rooms, {});
    for (size_t c = 0; c < rooms; ++c) {
        out.overlay_first[c] = static_cast<int>(out.overlay.size());
        for (const CacheChart& chart : charts) {
            if (chart.room != static_cast<int>(c)) continue;
            const std::vector<glm::ivec4> rects = edge_rects(chart, out);
            if (rects.empty()) continue;
            CacheOverlayPiece piece;
            piece.first = static_cast<int>(out.overlay.size());
            glm::ivec2 lo_cell = glm::ivec2(rects[0].x, rects[0].y), hi_cell = glm::ivec2(rects[0].z, rects[0].w);
            for (const glm::ivec4& r : rects) {
                lo_cell = glm::min(lo_cell, glm::ivec2(r.x, r.y));
                hi_cell = glm::max(hi_cell, glm::ivec2(r.z, r.w));
            }
            for (const std::array<std::uint32_t, 3>& t : chart.triangles) {
                // The triangle's bounds in the chart's cells.
                glm::dvec2 lo(1e300), hi(-1e300);
                for (const std::uint32_t v : t) {
                    const glm::dvec2 q = chart.atlas_point(glm::dvec3((*in.vertices)[v].position)) - glm::dvec2(chart.at);
                    lo = glm::min(lo, q);
                    hi = glm::max(hi, q);
                }
                const bool meets = std::any_of(rects.begin(), rects.end(), [&](const glm::ivec4& r) {
                    return lo.x <= r.z + 0.25 && hi.x >= r.x - 0.25 && lo.y <= r.w + 0.25 && hi.y >= r.y - 0.25;
                });
                if (meets) out.overlay.insert(out.overlay.end(), t.begin(), t.end());
            }
            piece.count = static_cast<int>(out.overlay.size()) - piece.first;
            // The cells' corners, a quarter of a cell wider.
            const glm::dvec2 a = chart.lo + chart.side * (glm::dvec2(lo_cell) - 1.25);
            const glm::dvec2 b = chart.lo + chart.side * (glm::dvec2(hi_cell) - 0.75);
            for (int k = 0; k < 8; ++k)
                piece.corners[static_cast<size_t>(k)] = chart.point_at({(k & 1) ? b.x : a.x, (k & 2) ? b.y : a.y});
            if (piece.count > 0) out.overlay_pieces[c].push_back(piece);
        }
    }
    out.overlay_first[rooms] = static_cast<int>(out.overlay.size());
}

}  // namespace impossible::render
