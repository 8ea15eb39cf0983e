// --pose without --room in a layout with a prism room (layout-format.md,
// "Rooms of any shape": "the room whose prism holds the head"): an L whose
// notch a box room fills. A head in the notch is in the box only (the L's
// bounding box holds it too), one in an arm of the L in the L only, one on
// their shared wall in both.
#include <string>

#include <gtest/gtest.h>

#include "cli/view_options.hpp"
#include "common/layouts.hpp"

namespace impossible::cli {
namespace {

// frame_for on a session of its own (it may replace the session by the
// pairing at --path's frame).
render::FrameDesc prism_frame_in(session::Session session, const ViewOptions& o) { return frame_for(session, o); }

layout::Layout l_and_notch() {
    layout::Layout l;
    l.source = "ell.json";
    l.rooms.push_back(impossible::test::prism_room("ell", {{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}}, 0.0, 3.0));
    impossible::test::add_room(l, "notch", {2, 0, 2}, {4, 3, 4});
    l.start.room = 0;
    return l;
}

int room_at(const layout::Layout& l, const std::string& pose) {
    const ViewTables& table = view_options();
    return prism_frame_in(session::Session(l), parse_view_options(parse_args({"--pose", pose}, 1, table), table)).room;
}

std::string room_error(const layout::Layout& l, const std::string& pose) {
    try {
        room_at(l, pose);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no InputError)";
}

TEST(PrismRoomOptions, PoseFindsTheRoomWhosePrismHoldsTheHead) {
    const layout::Layout l = l_and_notch();
    EXPECT_EQ(room_at(l, "3,1.6,3,0,0,0"), 1);    // in the notch: the box only
    EXPECT_EQ(room_at(l, "1,1.6,3.5,0,0,0"), 0);  // the L's north arm
    EXPECT_EQ(room_at(l, "3.5,1.6,1,0,0,0"), 0);  // its east arm
    EXPECT_EQ(room_error(l, "2,1.6,3,0,0,0"), "--pose: the head is in several rooms (ell, notch); give --room");
    EXPECT_EQ(room_error(l, "5,1.6,3,0,0,0"), "--pose: the head is in no room; give --room");
    // Without the box, the notch is in no room.
    layout::Layout alone = l;
    alone.rooms.pop_back();
    EXPECT_EQ(room_error(alone, "3,1.6,3,0,0,0"), "--pose: the head is in no room; give --room");
}

}  // namespace
}  // namespace impossible::cli
