// A volume's target room in pieces (scene/volume_pieces.hpp): the triangles
// that may lie inside the volume, in order, each piece bounding where its
// triangles meet the box.
#include <gtest/gtest.h>

#include <random>

#include "math/portal.hpp"
#include "scene/volume_pieces.hpp"
#include "scene_test_helpers.hpp"

namespace impossible::scene::test {
namespace {

// "lab" (room 0) with a volume showing "past" (room 1), where one prop stands
// inside the volume, one across its side and one far from it.
layout::Layout volume_layout(const math::PortalRect& rect) {
    layout::Layout l = one_room_layout();
    l.rooms.push_back(make_room("past", {-2.0, 0.0, -2.0}, {2.0, 3.0, 2.0}));
    l.rooms[1].props.push_back(box_prop({1.2, 0.0, 1.2}, {1.8, 0.5, 1.8}));     // far from it
    l.rooms[1].props.push_back(box_prop({-0.2, 0.0, -1.2}, {0.2, 0.4, -0.8}));  // inside
    l.rooms[1].props.push_back(box_prop({0.3, 0.0, -1.0}, {1.0, 0.6, -0.6}));   // across its +x side
    layout::Volume v;
    v.id = "scanner";
    v.room = 0;
    v.rect = rect;
    v.target_room = 1;
    l.volumes.push_back(v);
    return l;
}

math::PortalRect scanner_rect(glm::dvec3 normal) {
    math::PortalRect r;
    r.center = {0.0, 1.2, -1.0};
    r.normal = glm::normalize(normal);
    r.up = {0.0, 1.0, 0.0};
    r.width = 1.0;
    r.height = 2.6;
    r.depth = 1.4;
    return r;
}

// A point in the box's coordinates, each axis in units of its half extent.
glm::dvec3 in_box(const math::PortalRect& r, const glm::dvec3& p) {
    const glm::dvec3 d = p - r.center;
    return {glm::dot(d, math::portal_right(r)) / (0.5 * r.width), glm::dot(d, r.up) / (0.5 * r.height),
            glm::dot(d, r.normal) / (0.5 * r.depth)};
}

glm::dvec3 origin_of(const Scene& s) { return s.origins[1].origin; }

bool inside(const glm::dvec3& q) { return std::abs(q.x) < 1.0 && std::abs(q.y) < 1.0 && std::abs(q.z) < 1.0; }

void expect_pieces_hold_what_the_volume_shows(const math::PortalRect& rect, const char* what) {
    SCOPED_TRACE(what);
    const layout::Layout l = volume_layout(rect);
    const Scene s = build_scene(l);
    ASSERT_EQ(s.volume_pieces.size(), 2u);
    ASSERT_EQ(s.volume_pieces[0].size(), 1u);
    EXPECT_TRUE(s.volume_pieces[1].empty());
    const std::vector<VolumePiece>& pieces = s.volume_pieces[0][0];
    ASSERT_FALSE(pieces.empty());
    EXPECT_LE(pieces.size(), kVolumeMostPieces);
    // In order, disjoint, each within one of the target's batches and with its state.
    std::uint32_t end = 0, kept = 0, all = 0;
    for (const DrawBatch& b : s.batches[1]) all += b.range.count;
    for (const VolumePiece& p : pieces) {
        EXPECT_GE(p.batch.range.first, end);
        EXPECT_EQ(p.batch.range.count % 3, 0u);
        end = p.batch.range.first + p.batch.range.count;
        kept += p.batch.range.count;
        bool within = false;
        for (const DrawBatch& b : s.batches[1])
            within = within || (p.batch.range.first >= b.range.first && end <= b.range.first + b.range.count &&
                                p.batch.same_state(b));
        EXPECT_TRUE(within) << p.batch.range.first;
    }
    EXPECT_LT(kept, all) << kept << " of " << all << " indices";
    // The ceiling and the far prop are left out.
    for (const VolumePiece& p : pieces)
        for (std::uint32_t i = p.batch.range.first; i < p.batch.range.first + p.batch.range.count; i += 3) {
            bool ceiling = true, far_prop = true;
            for (std::uint32_t k = i; k < i + 3; ++k) {
                const glm::dvec3 v = origin_of(s) + glm::dvec3(s.vertices[s.indices[k]].position);
                ceiling = ceiling && v.y > 2.9;
                far_prop = far_prop && std::min(v.x, v.z) > 1.1 && std::max(v.x, v.z) < 1.9;
            }
            EXPECT_FALSE(ceiling) << "a ceiling triangle, index " << i;
            EXPECT_FALSE(far_prop) << "a triangle of the far prop, index " << i;
        }
    // Every point of the target's triangles inside the box is in a piece,
    // within that piece's bounds.
    std::mt19937 rng(39);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const glm::dvec3 origin = s.origins[1].origin;
    int points_inside = 0;
    for (const DrawBatch& b : s.batches[1])
        for (std::uint32_t i = b.range.first; i + 3 <= b.range.first + b.range.count; i += 3) {
            const VolumePiece* holder = nullptr;
            for (const VolumePiece& p : pieces)
                if (i >= p.batch.range.first && i < p.batch.range.first + p.batch.range.count) holder = &p;
            for (int k = 0; k < 64; ++k) {
                double a = unit(rng), c = unit(rng);
                if (a + c > 1.0) a = 1.0 - a, c = 1.0 - c;
                const glm::dvec3 p = origin + (1.0 - a - c) * glm::dvec3(s.vertices[s.indices[i]].position) +
                                     a * glm::dvec3(s.vertices[s.indices[i + 1]].position) +
                                     c * glm::dvec3(s.vertices[s.indices[i + 2]].position);
                const glm::dvec3 q = in_box(rect, p);
                if (!inside(q)) continue;
                ++points_inside;
                ASSERT_NE(holder, nullptr) << "triangle at index " << i;
                glm::dvec3 lo(INFINITY), hi(-INFINITY);
                for (const glm::dvec3& corner : holder->corners) {
                    lo = glm::min(lo, in_box(rect, corner));
                    hi = glm::max(hi, in_box(rect, corner));
                }
                for (int axis = 0; axis < 3; ++axis) {
                    EXPECT_GE(q[axis], lo[axis] - 1e-9);
                    EXPECT_LE(q[axis], hi[axis] + 1e-9);
                }
            }
        }
    EXPECT_GT(points_inside, 100);
}

TEST(VolumePieces, HoldEveryTriangleInsideTheVolumeWithinTheirBounds) {
    expect_pieces_hold_what_the_volume_shows(scanner_rect({0.0, 0.0, 1.0}), "square to the room");
    expect_pieces_hold_what_the_volume_shows(scanner_rect({1.0, 0.0, 2.0}), "turned");
}

TEST(VolumePieces, AFaceInsideTheVolumeIsOnePieceBoundedWhereItMeetsIt) {
    // The floor's part inside the box (and the inside prop's bottom): flat,
    // no wider than the box.
    const math::PortalRect rect = scanner_rect({0.0, 0.0, 1.0});
    const Scene s = build_scene(volume_layout(rect));
    int floors = 0;
    for (const VolumePiece& p : s.volume_pieces[0][0]) {
        glm::dvec3 lo(INFINITY), hi(-INFINITY);
        for (const glm::dvec3& c : p.corners) {
            lo = glm::min(lo, c);
            hi = glm::max(hi, c);
        }
        if (hi.y > 1e-9) continue;
        ++floors;
        EXPECT_NEAR(lo.y, 0.0, 1e-9);
        EXPECT_GE(lo.x, -0.5 * 1.0 * (1.0 + kVolumeKeepShare) - kVolumeKeepMetres - 1e-9);
        EXPECT_LE(hi.x, 0.5 * 1.0 * (1.0 + kVolumeKeepShare) + kVolumeKeepMetres + 1e-9);
        EXPECT_LE(hi.z, -1.0 + 0.5 * 1.4 * (1.0 + kVolumeKeepShare) + kVolumeKeepMetres + 1e-9);
    }
    EXPECT_GE(floors, 1);
}

TEST(VolumePieces, PastTheBudgetTheTargetIsDrawnWholeWithinTheBox) {
    const math::PortalRect rect = scanner_rect({0.0, 0.0, 1.0});
    const layout::Layout l = volume_layout(rect);
    const Scene s = build_scene(l);
    std::size_t triangles = 0;
    for (const DrawBatch& b : s.batches[1]) triangles += b.range.count / 3;
    // Within the budget: the pieces build_scene made, and the budget spent.
    std::size_t budget = triangles;
    const std::vector<VolumePiece> cut = volume_pieces(s, s.batches[1], s.origins[1].origin, l.volumes[0], budget);
    EXPECT_EQ(budget, 0u);
    ASSERT_EQ(cut.size(), s.volume_pieces[0][0].size());
    for (size_t k = 0; k < cut.size(); ++k)
        EXPECT_EQ(cut[k].batch.range.first, s.volume_pieces[0][0][k].batch.range.first);
    // Past it: each batch whole, bounded by the grown box, and nothing spent.
    budget = triangles - 1;
    const std::vector<VolumePiece> whole = volume_pieces(s, s.batches[1], s.origins[1].origin, l.volumes[0], budget);
    EXPECT_EQ(budget, triangles - 1);
    ASSERT_EQ(whole.size(), s.batches[1].size());
    for (size_t k = 0; k < whole.size(); ++k) {
        EXPECT_EQ(whole[k].batch.range.first, s.batches[1][k].range.first);
        EXPECT_EQ(whole[k].batch.range.count, s.batches[1][k].range.count);
        for (const glm::dvec3& corner : whole[k].corners) {
            const glm::dvec3 q = in_box(rect, corner);
            for (int axis = 0; axis < 3; ++axis) {
                const double half = 0.5 * std::array{rect.width, rect.height, rect.depth}[static_cast<size_t>(axis)];
                EXPECT_NEAR(std::abs(q[axis]), 1.0 + kVolumeKeepShare + kVolumeKeepMetres / half, 1e-9);
            }
        }
    }
}

}  // namespace
}  // namespace impossible::scene::test
