// Which renderers' buffers the headless share releases before and after a
// frame (api/headless_share.hpp, releases_needed): the least recently drawn
// first, only as many as bring the rest and the frame within the bound, and
// none for a frame that alone passes it (refused before it makes anything).
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "api/headless_share.hpp"

namespace impossible {
namespace {

TEST(HeadlessShare, ReleasesTheLeastRecentlyDrawnUntilTheFrameFits) {
    const std::vector<std::int64_t> kept = {40, 0, 30, 20};  // least recently drawn first
    EXPECT_EQ(api::releases_needed(kept, 10, 100), 0u);      // 90 + 10: within
    EXPECT_EQ(api::releases_needed(kept, 11, 100), 1u);      // 101: the first goes
    EXPECT_EQ(api::releases_needed(kept, 50, 100), 1u);      // 50 + 50
    EXPECT_EQ(api::releases_needed(kept, 51, 100), 3u);      // the empty one costs nothing to pass
    EXPECT_EQ(api::releases_needed(kept, 81, 100), 4u);      // all of them
    EXPECT_EQ(api::releases_needed(kept, 100, 100), 4u);
    EXPECT_EQ(api::releases_needed(kept, 101, 100), 0u);  // refused anyway: keep the others'
    EXPECT_EQ(api::releases_needed({}, 100, 100), 0u);
}

}  // namespace
}  // namespace impossible
