// The minimap draws a prism room's floor polygon (layout-format.md, "Rooms
// of any shape"), not its bounding rectangle.
#include <gtest/gtest.h>

#include <vector>

#include <glm/geometric.hpp>

#include "../common/layouts.hpp"
#include "preview/minimap.hpp"
#include "walk/walker.hpp"

namespace impossible::preview {
namespace {

std::vector<std::pair<glm::vec4, glm::vec4>> lines_of(const OverlayBatch& batch, glm::vec4 colour) {
    std::vector<std::pair<glm::vec4, glm::vec4>> out;
    for (std::size_t i = 0; i + 1 < batch.lines.size(); i += 2)
        if (batch.lines[i].color == colour) out.push_back({batch.lines[i].position, batch.lines[i + 1].position});
    return out;
}

TEST(PreviewMinimap, APrismRoomIsDrawnAsItsPolygon) {
    layout::Layout l;
    // An L (4 x 4 m without its north-east quarter) beside a 2 x 2 m box room.
    l.rooms.push_back(test::prism_room("ell", {{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}}, 0.0, 3.0));
    l.rooms.push_back(test::make_room("box", {5, 0, 0}, {7, 3, 2}));
    l.start.room = 0;
    l.start.position = {1.0, 1.6, 1.0};
    const walk::Walker walker(l);
    const glm::vec4 current{1.0f, 0.95f, 0.5f, 1.0f};  // the head's room
    auto draw = [&](int room) {
        MinimapInput in;
        in.layout = &l;
        in.room = room;
        in.transfer = &walker.links().transfer;
        in.physical_head.position = l.start.position;
        OverlayBatch batch;
        batch.width = batch.height = 400;
        add_minimap(batch, in, {10.0f, 10.0f}, 300.0f);
        return lines_of(batch, current);
    };
    const auto ell = draw(0);
    ASSERT_EQ(ell.size(), 6u);  // one line per wall
    // Consecutive walls meet: a closed outline.
    for (std::size_t i = 0; i < ell.size(); ++i)
        EXPECT_LT(glm::distance(ell[i].second, ell[(i + 1) % ell.size()].first), 1e-5f) << "wall " << i;
    const auto box = draw(1);
    EXPECT_EQ(box.size(), 4u);  // a box room keeps its rectangle
}

}  // namespace
}  // namespace impossible::preview
