// The designer's report and volume portals: a volume's target room is seen,
// not walked into, so it is neither unreachable nor a noticeable overlap.
#include <gtest/gtest.h>

#include "design/report.hpp"
#include "layout/layout.hpp"

namespace impossible {
namespace {

const char* const kLab = R"({
  "format": "impossible-layout", "version": 1,
  "start": { "room": "lab", "position": [0, 1.6, 1] },
  "rooms": [
    { "id": "lab", "min": [-2, 0, -2], "max": [2, 3, 2] },
    { "id": "lab_past", "min": [-2, 0, -2], "max": [2, 3, 2] },
    { "id": "attic", "min": [-2, 0, -2], "max": [2, 3, 2] }
  ],
  "portals": [
    { "id": "scanner", "room": "lab", "kind": "volume", "target": "lab_past",
      "center": [0, 1.2, 0], "normal": [0, 0, 1], "width": 1, "height": 2, "depth": 1 }
  ]
})";

TEST(VolumeReport, TheTargetRoomIsSeenNotUnreachable) {
    const layout::LoadResult loaded = layout::load_layout_text(kLab, "lab.json", ".");
    ASSERT_TRUE(loaded.layout) << (loaded.errors.empty() ? "" : loaded.errors[0].str());
    const design::Report r = design::make_report(*loaded.layout);
    // The attic, which nothing leads to or shows, is still unreachable.
    EXPECT_EQ(r.unreachable, std::vector<int>{2});
    ASSERT_FALSE(r.overlaps.empty());
    for (const design::Overlap& o : r.overlaps) {
        const bool with_past = o.a == 1 || o.b == 1;
        EXPECT_EQ(o.noticeable, !with_past) << o.a << "/" << o.b;
    }
}

}  // namespace
}  // namespace impossible
