// The dynamic objects' meshes (scene/object_meshes.hpp): a prop that moves or
// meets a door at rest leaves its cell and gets a mesh of its own, measured
// from its listed room's origin; static props stay in their cells; the hand
// is the last mesh.
#include <gtest/gtest.h>

#include "scene/scene.hpp"
#include "scene_test_helpers.hpp"

namespace impossible::scene::test {
namespace {

TEST(ObjectMeshes, DynamicPropsLeaveTheirCells) {
    layout::Layout l = one_room_layout();
    l.rooms.push_back(make_room("other", {-2.0, 0.0, -2.0}, {2.0, 3.0, 2.0}));
    impossible::test::add_pair(l, make_portal("a", 0, {0.0, 1.0, 0.0}, {0, 0, 1}, 1.0, 2.0),
                               make_portal("b", 1, {0.0, 1.0, 0.0}, {0, 0, -1}, 1.0, 2.0));
    l.rooms[0].props.push_back(box_prop({1.0, 0.0, 1.0}, {1.5, 0.5, 1.5}));    // static
    l.rooms[0].props.push_back(box_prop({-0.2, 0.0, -0.2}, {0.2, 0.4, 0.2}));  // half through the door
    layout::BoxProp moving = box_prop({-1.5, 0.0, 1.0}, {-1.0, 0.5, 1.5});
    moving.id = "m";
    moving.motion.keys = {{0.0, {0.0, 0.0, 0.0}}, {1.0, {0.0, 0.0, -1.0}}};
    l.rooms[0].props.push_back(moving);
    const Scene s = build_scene(l);

    ASSERT_EQ(s.object_set.dynamic.size(), 2u);
    EXPECT_EQ(s.object_set.dynamic[0], (std::vector<bool>{false, true, true}));
    // Room 0 keeps one prop: 36 indices besides its faces.
    ASSERT_EQ(s.objects[0].objects.size(), 1u);
    EXPECT_NEAR(s.objects[0].objects[0].lo.x, 1.0, 1e-5);
    // Two dynamic props, then the hand.
    ASSERT_EQ(s.object_meshes.size(), 3u);
    EXPECT_NEAR(s.object_meshes[0].lo.x, -0.2, 1e-5);
    EXPECT_NEAR(s.object_meshes[0].hi.y, 0.4, 1e-5);
    EXPECT_NEAR(s.object_meshes[1].lo.x, -1.5, 1e-5);
    for (const ObjectMesh& m : s.object_meshes) {
        ASSERT_EQ(m.batches.size(), 1u);
        EXPECT_EQ(m.batches[0].range.count, 36u);
        EXPECT_EQ(m.origin, s.origins[0].origin);
    }
    // Their triangles are no cell's.
    const IndexRange cell = s.cells[0];
    for (const ObjectMesh& m : s.object_meshes) EXPECT_TRUE(m.batches[0].range.first >= cell.first + cell.count);
}

TEST(ObjectMeshes, VolumesAreListedPerRoom) {
    layout::Layout l = one_room_layout();
    l.rooms.push_back(make_room("past", {-2.0, 0.0, -2.0}, {2.0, 3.0, 2.0}));
    layout::Volume v;
    v.id = "v";
    v.room = 0;
    v.target_room = 1;
    l.volumes.push_back(v);
    const Scene s = build_scene(l);
    ASSERT_EQ(s.volumes.size(), 2u);
    ASSERT_EQ(s.volumes[0].size(), 1u);
    EXPECT_EQ(s.volumes[0][0].target_room, 1);
    EXPECT_TRUE(s.volumes[1].empty());
}

}  // namespace
}  // namespace impossible::scene::test
