// The tour planner on the example layouts, checked by replaying it with the
// walker (scene/walk.hpp).
#include "design_test_util.hpp"

#include <fstream>
#include <set>

#include "design/path_text.hpp"
#include "design/tour.hpp"
#include "layout/path_file.hpp"
#include "walk/walker.hpp"

namespace design_test {
namespace {

TEST(Tour, FourRoomsVisitsEveryRoomInsideThePlayArea) {
    const layout::Layout l = load_file("four_rooms.json");
    const auto tour = design::plan_tour(l);
    ASSERT_TRUE(tour.has_value()) << tour.error();
    EXPECT_EQ(tour->visited.size(), 4u);
    EXPECT_TRUE(tour->missed.empty());
    EXPECT_GE(tour->closest_edge, 0.1 - 1e-9);  // the planner's edge margin
    // Replayed independently: every room, and no step longer than the step size.
    walk::Walker walker(l);
    std::set<int> rooms;
    for (std::size_t i = 0; i < tour->poses.size(); ++i) {
        walker.step(tour->poses[i]);
        rooms.insert(walker.room());
        if (i > 1) {
            EXPECT_LE(glm::distance(tour->poses[i].position, tour->poses[i - 1].position), 0.05 + 1e-9);
        }
    }
    EXPECT_EQ(rooms.size(), 4u);
    EXPECT_EQ(tour->teleports, 6);  // hall → library → studio → garden, and back
}

TEST(Tour, GoesRoundProps) {
    // The default layout's rooms hold props: no pose comes within the body radius of a box prop.
    for (const char* name : {"default.json", "four_rooms.json"}) {
        const layout::Layout l = load_file(name);
        const auto tour = design::plan_tour(l);
        ASSERT_TRUE(tour.has_value());
        EXPECT_TRUE(tour->missed.empty()) << name;
        walk::Walker walker(l);
        for (std::size_t i = 0; i < tour->poses.size(); ++i) {
            walker.step(tour->poses[i]);
            const math::dvec3 p = walker.position();
            for (const layout::Prop& prop : l.rooms[walker.room()].props) {
                const auto* box = std::get_if<layout::BoxProp>(&prop);
                if (box == nullptr || box->min.y > 1.8) continue;
                const double dx = std::max({box->min.x - p.x, 0.0, p.x - box->max.x});
                const double dz = std::max({box->min.z - p.z, 0.0, p.z - box->max.z});
                EXPECT_GT(std::hypot(dx, dz), 0.2) << name << " pose " << i;
            }
        }
    }
}

TEST(Tour, TheTunnelIsMissedWhereItLeavesThePlayArea) {
    const layout::Layout l = load_file("tunnel.json");
    const auto tour = design::plan_tour(l);
    ASSERT_TRUE(tour.has_value());
    // The tunnel is entered (it starts inside the play area) even though most of it lies outside.
    EXPECT_EQ(tour->visited.size(), 2u);
    EXPECT_GE(tour->closest_edge, 0.0);
}

TEST(Tour, PathTextReadsBack) {
    const layout::Layout l = load_file("default.json");
    const auto tour = design::plan_tour(l);
    ASSERT_TRUE(tour.has_value());
    const std::string file = ::testing::TempDir() + "tour_path.txt";
    {
        std::ofstream out(file);
        out << design::path_text(tour->poses, "a test\nof two lines");
    }
    const auto back = layout::read_path_file(file);
    ASSERT_TRUE(back.has_value()) << back.error();
    ASSERT_EQ(back->size(), tour->poses.size());
    EXPECT_NEAR((*back)[5].position.x, tour->poses[5].position.x, 1e-4);
}

}  // namespace
}  // namespace design_test
