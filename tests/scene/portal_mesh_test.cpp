// Portal boxes (front facing +n, inner faces inwards) and the index ranges.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/scene.hpp"
#include "scene_test_helpers.hpp"
#include "shading/shading.hpp"

namespace impossible::scene::test {
namespace {

// Front in the plane facing +n, inner faces facing the box's centre; all
// with the fill colour and the geometric normal; front and inner together a
// closed box.
void expect_portal_box(const Scene& s, const PortalMesh& m, const math::PortalRect& rect) {
    const auto front = triangles(s, m.front);
    const auto inner = triangles(s, m.inner);
    ASSERT_FALSE(front.empty());
    const glm::vec3 fill(shading::kPortalFillColor);
    for (const Triangle& t : front) {
        ASSERT_GT(t.area(), 0.0);
        EXPECT_NEAR(glm::length(t.geometric_normal() - rect.normal), 0.0, 1e-6);
        for (const Vertex* v : t.v) {
            EXPECT_NEAR(math::signed_distance(rect, glm::dvec3(v->position)), 0.0, 1e-6);
            EXPECT_NEAR(glm::length(glm::dvec3(v->normal) - rect.normal), 0.0, 1e-6);
            EXPECT_EQ(v->color, fill);
            EXPECT_EQ(v->checker, 0.0f);
        }
    }
    EXPECT_NEAR(total_area(front), rect.width * rect.height, 1e-5);
    const glm::dvec3 centre = rect.center - 0.5 * rect.depth * rect.normal;
    for (const Triangle& t : inner) {
        ASSERT_GT(t.area(), 0.0);
        const glm::dvec3 g = t.geometric_normal();
        EXPECT_GT(glm::dot(g, centre - t.centroid()), 0.0) << "inner face not facing inwards";
        for (const Vertex* v : t.v) {
            EXPECT_NEAR(glm::length(glm::dvec3(v->normal) - g), 0.0, 1e-6);
            EXPECT_EQ(v->color, fill);
            EXPECT_EQ(v->checker, 0.0f);
        }
    }
    const double sides = 2.0 * rect.depth * (rect.width + rect.height);
    EXPECT_NEAR(total_area(inner), sides + rect.width * rect.height, 1e-5);
    EXPECT_TRUE(closed_undirected(concat(front, inner)));
}

bool has_position(const std::vector<Triangle>& ts, const glm::vec3& p) {
    for (const Triangle& t : ts) {
        for (const Vertex* v : t.v) {
            if (v->position == p) return true;
        }
    }
    return false;
}

TEST(PortalMesh, FreeStandingBox) {
    layout::Layout l = one_room_layout();
    l.portals.push_back(make_portal("p0", 0, {0.25, 1.25, 0.5}, {0, 0, 1}, 1.0, 2.0, {0, 1, 0}, 0.5));
    const Scene s = build_scene(l);
    ASSERT_EQ(s.portals.size(), 1u);
    const PortalMesh& m = s.portals[0];
    EXPECT_EQ(m.front.count, 2u * 3);
    EXPECT_EQ(m.inner.count, 10u * 3);
    expect_portal_box(s, m, l.portals[0].rect);
    math::dvec3 c[8];
    math::box_corners(l.portals[0].rect, c);
    for (int k = 0; k < 4; ++k) EXPECT_TRUE(has_position(triangles(s, m.front), glm::vec3(c[k])));
    for (int k = 4; k < 8; ++k) EXPECT_TRUE(has_position(triangles(s, m.inner), glm::vec3(c[k])));
}

TEST(PortalMesh, TiltedFreeStandingBox) {
    layout::Layout l = one_room_layout();
    const double h = std::sqrt(0.5);
    const glm::dvec3 n = glm::normalize(glm::dvec3(1.0, 0.5, -0.25));
    const glm::dvec3 up = glm::normalize(glm::dvec3(0, 1, 0) - n.y * n);
    l.portals.push_back(make_portal("p0", 0, {0.1, 1.3, -0.2}, n, 0.75, 1.5, up, h));
    const Scene s = build_scene(l);
    EXPECT_EQ(s.cells[0].count, 36u);
    expect_portal_box(s, s.portals[0], l.portals[0].rect);
}

TEST(PortalMesh, HoleFrontMatchesTheWall) {
    layout::Layout l = one_room_layout();
    const auto wall = layout::Face::NegZ;
    l.portals.push_back(in_face(make_portal("p0", 0, {0.0, 1.0, -2.0}, {0, 0, 1}, 1.0, 2.0, {0, 1, 0}), wall));
    l.portals.push_back(in_face(make_portal("p0", 0, {0.0, 1.0, -2.0}, {0, 0, 1}, 2.0, 1.0, {1, 0, 0}), wall));
    l.portals.push_back(in_face(make_portal("p0", 0, {0.0, 1.0, -2.0}, {0, 0, 1}, 1.0, 2.0, {0, -1, 0}), wall));
    for (std::size_t p = 0; p < 3; ++p) {  // the door; the same hole with up = +x, and upside down
        layout::Layout one = l;
        one.portals = {l.portals[p]};
        const Scene s = build_scene(one);
        const PortalMesh& m = s.portals[0];
        expect_portal_box(s, m, one.portals[0].rect);
        // The front corners are exactly the box corners and the wall's hole corners.
        const auto walls = triangles(s, s.cells[0]);
        const auto front = triangles(s, m.front);
        math::dvec3 c[8];
        math::box_corners(one.portals[0].rect, c);
        for (int k = 0; k < 4; ++k) {
            EXPECT_TRUE(has_position(front, glm::vec3(c[k]))) << "portal " << p << " corner " << k;
            EXPECT_TRUE(has_position(walls, glm::vec3(c[k]))) << "portal " << p << " corner " << k;
        }
        // The front's boundary edges are the wall's hole edges, reversed.
        const auto wall_edges = directed_edges(walls);
        const auto front_edges = directed_edges(front);
        int boundary = 0;
        for (const auto& [e, count] : front_edges) {
            if (front_edges.count({e.second, e.first}) != 0) continue;  // inside the front
            ++boundary;
            EXPECT_EQ(wall_edges.count({e.second, e.first}), 1u);
        }
        EXPECT_EQ(boundary, 4);
    }
}

TEST(PortalMesh, RangesPartitionTheIndices) {
    layout::Layout l = one_room_layout();
    l.rooms.push_back(make_room("annex", {2, 0, -1}, {4, 2.5, 1}));
    layout::BoxProp box;
    box.min = {-0.5, 0.0, -0.5};
    box.max = {0.5, 1.0, 0.5};
    l.rooms[0].props.push_back(box);
    box.min = {2.5, 0.0, -0.5};
    box.max = {3.5, 1.0, 0.5};
    l.rooms[1].props.push_back(box);
    l.portals.push_back(
        in_face(make_portal("p0", 0, {2.0, 1.0, 0.0}, {-1, 0, 0}, 1.0, 2.0, {0, 1, 0}), layout::Face::PosX));
    l.portals.push_back(
        in_face(make_portal("p1", 1, {2.0, 1.0, 0.0}, {1, 0, 0}, 1.0, 2.0, {0, 1, 0}), layout::Face::NegX));
    l.portals.push_back(make_portal("p0", 0, {0.0, 1.0, 1.0}, {0, 0, -1}, 0.5, 0.5, {0, 1, 0}));
    const Scene s = build_scene(l);
    ASSERT_EQ(s.cells.size(), 2u);
    ASSERT_EQ(s.portals.size(), 3u);
    std::vector<IndexRange> ranges(s.cells.begin(), s.cells.end());
    for (const PortalMesh& m : s.portals) {
        ranges.push_back(m.front);
        ranges.push_back(m.inner);
    }
    // Then the dynamic objects' meshes: here only the hand's.
    ASSERT_EQ(s.object_meshes.size(), 1u);
    for (const DrawBatch& b : s.object_meshes[0].batches) ranges.push_back(b.range);
    std::uint32_t next = 0;
    for (const IndexRange& r : ranges) {
        EXPECT_EQ(r.first, next);
        EXPECT_GT(r.count, 0u);
        EXPECT_EQ(r.count % 3, 0u);
        next = r.first + r.count;
    }
    EXPECT_EQ(next, s.indices.size());
    for (const std::uint32_t i : s.indices) ASSERT_LT(i, s.vertices.size());
    // Both door portals are holes in their rooms: each room is closed by its
    // own door's front.
    // (A room's faces are its surfaces' batches; its props come before them.)
    for (std::size_t room = 0; room < 2; ++room) {
        ASSERT_EQ(s.objects[room].surfaces.size(), 1u);
        EXPECT_EQ(s.objects[room].surfaces[0].range.count, s.cells[room].count - 36);
        EXPECT_TRUE(closed_and_consistent(
            concat(triangles(s, s.objects[room].surfaces[0].range), triangles(s, s.portals[room].front))));
    }
    for (std::size_t p = 0; p < 3; ++p) expect_portal_box(s, s.portals[p], l.portals[p].rect);
}

TEST(PortalMesh, EmptyLayoutGivesOnlyTheHand) {
    const Scene s = build_scene(layout::Layout{});
    EXPECT_TRUE(s.cells.empty());
    EXPECT_TRUE(s.portals.empty());
    // The hand's box (layout::HandShape's default), whether or not a frame
    // has hands: 24 vertices, 36 indices.
    ASSERT_EQ(s.object_meshes.size(), 1u);
    EXPECT_EQ(s.vertices.size(), 24u);
    EXPECT_EQ(s.indices.size(), 36u);
    EXPECT_EQ(s.object_meshes[0].origin, glm::dvec3(0.0));
    EXPECT_NEAR(s.object_meshes[0].hi.x, 0.04, 1e-5);
    EXPECT_NEAR(s.object_meshes[0].lo.z, -0.08, 1e-5);
}

}  // namespace
}  // namespace impossible::scene::test
