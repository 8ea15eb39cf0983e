// volume_pieces (volume_pieces.hpp).
#include "scene/volume_pieces.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>

#include <glm/vector_relational.hpp>

#include "math/portal.hpp"

namespace impossible::scene {
namespace {

// A triangle clipped to the box grown to `reach` (Sutherland-Hodgman, in the
// box's coordinates): the bounds of what is left, or nullopt where nothing is.
std::optional<std::pair<glm::dvec3, glm::dvec3>> clipped_bounds(const std::array<glm::dvec3, 3>& triangle,
                                                                const glm::dvec3& reach) {
    // Most triangles lie wholly inside or wholly beyond one side.
    const glm::dvec3 lo0 = glm::min(triangle[0], glm::min(triangle[1], triangle[2]));
    const glm::dvec3 hi0 = glm::max(triangle[0], glm::max(triangle[1], triangle[2]));
    for (int a = 0; a < 3; ++a)
        if (lo0[a] > reach[a] || hi0[a] < -reach[a]) return std::nullopt;
    if (glm::all(glm::lessThanEqual(hi0, reach)) && glm::all(glm::greaterThanEqual(lo0, -reach)))
        return std::pair{lo0, hi0};
    // A triangle cut by six planes has at most nine corners.
    std::array<glm::dvec3, 12> polygon{}, next{};
    size_t count = 3, next_count = 0;
    std::copy(triangle.begin(), triangle.end(), polygon.begin());
    for (int plane = 0; plane < 6 && count > 0; ++plane) {
        const int axis = plane / 2;
        const double sign = plane % 2 == 0 ? 1.0 : -1.0;
        const auto inside = [&](const glm::dvec3& p) { return reach[axis] - sign * p[axis]; };
        next_count = 0;
        for (size_t k = 0; k < count; ++k) {
            const glm::dvec3& a = polygon[k];
            const glm::dvec3& b = polygon[(k + 1) % count];
            const double sa = inside(a), sb = inside(b);
            if (sa >= 0.0) next[next_count++] = a;
            if ((sa >= 0.0) != (sb >= 0.0)) next[next_count++] = a + (sa / (sa - sb)) * (b - a);
        }
        polygon.swap(next);
        count = next_count;
    }
    if (count == 0) return std::nullopt;
    glm::dvec3 lo = polygon[0], hi = polygon[0];
    for (size_t k = 1; k < count; ++k) {
        lo = glm::min(lo, polygon[k]);
        hi = glm::max(hi, polygon[k]);
    }
    // Clamped: the cut points' rounding may stray past the grown box.
    return std::pair{glm::max(lo, -reach), glm::min(hi, reach)};
}

// A piece before its corners: its batch and run, and its bounds in the
// box's coordinates.
struct Run {
    DrawBatch batch;
    glm::dvec3 lo{0.0}, hi{0.0};
    size_t source = 0;  // which of the target's batches
};

double surface(const glm::dvec3& lo, const glm::dvec3& hi) {
    const glm::dvec3 d = hi - lo;
    return d.x * d.y + d.y * d.z + d.z * d.x;
}

// The volume's box: its centre, axes and grown half extents, and the
// target's vertices in its coordinates.
struct BoxFrame {
    glm::dvec3 center{0.0};
    std::array<glm::dvec3, 3> axes{};
    glm::dvec3 reach{0.0};          // the half extents, grown
    glm::dvec3 target_origin{0.0};  // the target's vertices are relative to it

    glm::dvec3 local(const Scene& scene, std::uint32_t index) const {
        const glm::dvec3 p = glm::dvec3(scene.vertices[index].position) + target_origin - center;
        return {glm::dot(p, axes[0]), glm::dot(p, axes[1]), glm::dot(p, axes[2])};
    }
};

// The runs of each batch's triangles that meet the grown box, one face
// (triangles in one plane) each, at most kVolumePieceTriangles.
std::vector<Run> face_runs(const Scene& scene, const std::vector<DrawBatch>& target, const BoxFrame& box) {
    std::vector<Run> runs;
    for (size_t s = 0; s < target.size(); ++s) {
        const DrawBatch& b = target[s];
        bool open = false;
        glm::dvec3 plane_normal{0.0};
        double plane_offset = 0.0;
        for (std::uint32_t i = 0; i + 3 <= b.range.count; i += 3) {
            const std::uint32_t first = b.range.first + i;
            const std::array<glm::dvec3, 3> t{box.local(scene, scene.indices[first]),
                                              box.local(scene, scene.indices[first + 1]),
                                              box.local(scene, scene.indices[first + 2])};
            const std::optional<std::pair<glm::dvec3, glm::dvec3>> bounds = clipped_bounds(t, box.reach);
            if (!bounds) {
                open = false;
                continue;
            }
            const glm::dvec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
            const double length = glm::length(n);
            const glm::dvec3 unit = length > 0.0 ? n / length : glm::dvec3(0.0);
            const bool same_plane =
                glm::dot(unit, plane_normal) > 1.0 - 1e-9 && std::abs(glm::dot(unit, t[0]) - plane_offset) <= 1e-6;
            if (!open || !same_plane || runs.back().batch.range.count >= 3 * kVolumePieceTriangles) {
                runs.push_back({b, bounds->first, bounds->second, s});
                runs.back().batch.range = {first, 0};
                plane_normal = unit;
                plane_offset = glm::dot(unit, t[0]);
                open = true;
            }
            Run& run = runs.back();
            run.batch.range.count += 3;
            run.lo = glm::min(run.lo, bounds->first);
            run.hi = glm::max(run.hi, bounds->second);
        }
    }
    return runs;
}

// Runs k and k + 1 of one batch as one: the triangles between them (none
// meets the box) are drawn too, and discarded as before.
Run joined(const Run& a, const Run& b) {
    Run j = a;
    j.batch.range.count = b.batch.range.first + b.batch.range.count - a.batch.range.first;
    j.lo = glm::min(a.lo, b.lo);
    j.hi = glm::max(a.hi, b.hi);
    return j;
}

// Fewer draws: neighbours of one batch joined, first pairwise while there
// are many (a large model), then the pair whose bounds grow least, down to
// kVolumeMostPieces.
void join_runs(std::vector<Run>& runs) {
    const auto mergeable = [&](size_t k) { return runs[k].source == runs[k + 1].source; };
    while (runs.size() > 4 * kVolumeMostPieces) {
        std::vector<Run> fewer;
        for (size_t k = 0; k < runs.size(); ++k)
            if (k + 1 < runs.size() && mergeable(k)) {
                fewer.push_back(joined(runs[k], runs[k + 1]));
                ++k;
            } else {
                fewer.push_back(runs[k]);
            }
        if (fewer.size() == runs.size()) break;
        runs.swap(fewer);
    }
    while (runs.size() > kVolumeMostPieces) {
        size_t best = runs.size();
        double growth = INFINITY;
        for (size_t k = 0; k + 1 < runs.size(); ++k) {
            if (!mergeable(k)) continue;
            const Run j = joined(runs[k], runs[k + 1]);
            const double g =
                surface(j.lo, j.hi) - surface(runs[k].lo, runs[k].hi) - surface(runs[k + 1].lo, runs[k + 1].hi);
            if (g < growth) {
                growth = g;
                best = k;
            }
        }
        if (best == runs.size()) break;
        runs[best] = joined(runs[best], runs[best + 1]);
        runs.erase(runs.begin() + static_cast<std::ptrdiff_t>(best) + 1);
    }
}

}  // namespace

std::vector<VolumePiece> volume_pieces(const Scene& scene, const std::vector<DrawBatch>& target,
                                       const glm::dvec3& target_origin, const layout::Volume& volume,
                                       std::size_t& budget) {
    const math::PortalRect& rect = volume.rect;
    BoxFrame box{rect.center, {math::portal_right(rect), rect.up, rect.normal}, glm::dvec3(0.0), target_origin};
    for (int a = 0; a < 3; ++a) {
        const double half = 0.5 * std::array{rect.width, rect.height, rect.depth}[static_cast<size_t>(a)];
        box.reach[a] = half * (1.0 + kVolumeKeepShare) + kVolumeKeepMetres;
    }
    std::size_t triangles = 0;
    for (const DrawBatch& b : target) triangles += b.range.count / 3;
    std::vector<Run> runs;
    if (triangles <= budget) {
        budget -= triangles;
        runs = face_runs(scene, target, box);
    } else {
        // Past the budget: each batch whole, within the grown box's bounds.
        for (size_t k = 0; k < target.size(); ++k) runs.push_back({target[k], -box.reach, box.reach, k});
    }
    join_runs(runs);
    std::vector<VolumePiece> pieces;
    for (const Run& run : runs) {
        VolumePiece piece{run.batch, {}};
        for (int k = 0; k < 8; ++k) {
            const glm::dvec3 q(k == 0 || k == 3 || k == 4 || k == 7 ? run.lo.x : run.hi.x,
                               k % 4 < 2 ? run.lo.y : run.hi.y, k < 4 ? run.hi.z : run.lo.z);
            piece.corners[static_cast<size_t>(k)] =
                box.center + q.x * box.axes[0] + q.y * box.axes[1] + q.z * box.axes[2];
        }
        pieces.push_back(piece);
    }
    return pieces;
}

}  // namespace impossible::scene
