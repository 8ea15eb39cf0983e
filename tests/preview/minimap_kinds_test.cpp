// The minimap with mirrors and windows: drawn in colours of their own, and
// neither taken for a door (no room is shown one mirror or window away).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "layout/layout.hpp"
#include "preview/minimap.hpp"
#include "walk/walker.hpp"

namespace impossible::preview {
namespace {

int count_lines(const OverlayBatch& batch, glm::vec4 colour) {
    int n = 0;
    for (std::size_t i = 0; i + 1 < batch.lines.size(); i += 2) n += batch.lines[i].color == colour;
    return n;
}

OverlayBatch minimap_of(const layout::Layout& l, int room) {
    const walk::Walker walker(l);
    MinimapInput in;
    in.layout = &l;
    in.room = room;
    in.transfer = &walker.links().transfer;
    in.physical_head.position = l.start.position;
    OverlayBatch batch;
    batch.width = 400;
    batch.height = 400;
    add_minimap(batch, in, {10.0f, 10.0f}, 300.0f);
    return batch;
}

TEST(PreviewMinimap, MirrorsAndWindowsHaveColoursOfTheirOwn) {
    const glm::vec4 door = minimap_portal_colour(layout::PortalKind::Door);
    const glm::vec4 mirror = minimap_portal_colour(layout::PortalKind::Mirror);
    const glm::vec4 window = minimap_portal_colour(layout::PortalKind::Window);
    EXPECT_NE(door, mirror);
    EXPECT_NE(door, window);
    EXPECT_NE(mirror, window);

    const layout::LoadResult r =
        layout::load_layout_file(std::string(IMPOSSIBLE_TEST_DATA) + "/layouts/mirrors_windows.json");
    ASSERT_TRUE(r.layout.has_value());
    const layout::Layout& l = *r.layout;
    // The hall: a door, a mirror and a window.
    const OverlayBatch batch = minimap_of(l, 0);
    // Each portal: its rectangle's four sides (seen from above, two of them
    // coincide) and its normal.
    EXPECT_GE(count_lines(batch, door), 2);
    EXPECT_GE(count_lines(batch, mirror), 2);
    EXPECT_GE(count_lines(batch, window), 2);
    // The rooms one door away are those of the layout without its mirror and
    // window: the annex seen through the window is not drawn a second time.
    layout::Layout doors_only = l;
    std::erase_if(doors_only.portals, [](const layout::Portal& p) { return p.kind != layout::PortalKind::Door; });
    const glm::vec4 neighbour{0.35f, 0.55f, 1.0f, 0.7f};
    EXPECT_GT(count_lines(batch, neighbour), 0);
    EXPECT_EQ(count_lines(batch, neighbour), count_lines(minimap_of(doors_only, 0), neighbour));
    EXPECT_EQ(count_lines(minimap_of(doors_only, 0), mirror), 0);
}

}  // namespace
}  // namespace impossible::preview
