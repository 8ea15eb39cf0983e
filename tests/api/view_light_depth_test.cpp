// View::light_depth of the public API reaches the frame as --light-depth
// does (cli.md, "Time, hands and lights"), within 0..16.
#include <gtest/gtest.h>

#include "api/api_data.hpp"
#include "impossible/impossible.hpp"

namespace impossible::api {
namespace {

TEST(ApiViewLightDepth, ReachesTheLibrarysViewWithinItsRange) {
    const Layout layout = Layout::builtin();
    View view;
    EXPECT_FALSE(resolve_view(layout.data().layout, view)->light_depth);  // none: the layout's
    view.light_depth = 16;
    const Result<math::View> v = resolve_view(layout.data().layout, view);
    ASSERT_TRUE(v) << v.error();
    EXPECT_EQ(v->light_depth, 16);
    view.light_depth = 17;
    const Expected<Frame> traced = trace(layout, view);
    ASSERT_FALSE(traced);
    EXPECT_EQ(traced.error().message, "light_depth 17 is not in 0..16");
    view.light_depth = -1;
    EXPECT_FALSE(resolve_view(layout.data().layout, view));
}

}  // namespace
}  // namespace impossible::api
