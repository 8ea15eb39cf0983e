// View::time and View::hands of the public API reach the frame the
// renderer and the tracer draw, as --time and --hands do (cli.md, "Time,
// hands and lights").
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "api/api_data.hpp"
#include "impossible/impossible.hpp"

namespace impossible::api {
namespace {

TEST(ApiViewHands, TimeAndHandsReachTheLibrarysView) {
    const Layout layout = Layout::builtin();
    View view;
    view.time = 2.75;
    view.hands = std::array<Pose, 2>{Pose{-0.2, 1.3, 0.5, 10, -20, 5}, Pose{0.2, 1.4, 0.3, -30, 15, 0}};
    const Result<math::View> v = resolve_view(layout.data().layout, view);
    ASSERT_TRUE(v) << v.error();
    EXPECT_EQ(v->time, 2.75);
    ASSERT_TRUE(v->hands);
    EXPECT_EQ((*v->hands)[0].position, math::dvec3(-0.2, 1.3, 0.5));
    EXPECT_EQ((*v->hands)[0].yaw_deg, 10.0);
    EXPECT_EQ((*v->hands)[0].pitch_deg, -20.0);
    EXPECT_EQ((*v->hands)[0].roll_deg, 5.0);
    EXPECT_EQ((*v->hands)[1].position, math::dvec3(0.2, 1.4, 0.3));
    EXPECT_EQ((*v->hands)[1].yaw_deg, -30.0);
    EXPECT_EQ((*v->hands)[1].pitch_deg, 15.0);
    // None: no hands, time 0.
    const Result<math::View> plain = resolve_view(layout.data().layout, View{});
    ASSERT_TRUE(plain);
    EXPECT_FALSE(plain->hands);
    EXPECT_EQ(plain->time, 0.0);
}

TEST(ApiViewHands, NumbersThatAreNotFiniteAreErrors) {
    const Layout layout = Layout::builtin();
    View view;
    view.hands = std::array<Pose, 2>{Pose{0, 1, 0, 0, 0, 0}, Pose{0, std::nan(""), 0, 0, 0, 0}};
    const Expected<Frame> traced = trace(layout, view);
    ASSERT_FALSE(traced);
    EXPECT_EQ(traced.error().message, "the hands hold a number that is not finite");
    View later;
    later.time = std::numeric_limits<double>::infinity();
    const Expected<Frame> at_infinity = trace(layout, later);
    ASSERT_FALSE(at_infinity);
    EXPECT_EQ(at_infinity.error().message, "time is not a finite number");
}

}  // namespace
}  // namespace impossible::api
