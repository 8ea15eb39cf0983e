// `trace --pose` and `render --pose` without --room in a layout with an
// L-shaped prism room (layout-format.md, "Rooms of any shape": the room whose
// prism holds the head): a box room fills the L's notch, so a head in the
// notch is in the box only, one in the L's arm in the L only; without the
// box, the notch is in no room (exit 1, one line), and a head on the wall
// between the two is in both (exit 1, one line).
#include "hostile/hostile_util.hpp"

namespace impossible::hostile {
namespace {

std::string l_layout(bool with_notch) {
    return std::string(
               "{ \"format\": \"impossible-layout\", \"version\": 1,\n"
               "  \"start\": { \"room\": \"ell\", \"position\": [1, 1.6, 1] },\n"
               "  \"rooms\": [\n"
               "    { \"id\": \"ell\", \"floor\": [[0, 0], [4, 0], [4, 2], [2, 2], [2, 4], [0, 4]], "
               "\"y\": [0, 3] }") +
           (with_notch ? ",\n    { \"id\": \"notch\", \"min\": [2, 0, 2], \"max\": [4, 3, 4] }" : "") + "\n  ]\n}\n";
}

class HostilePrismPose : public Hostile {};

TEST_F(HostilePrismPose, TheNotchOfAnLIsInTheBoxThatFillsIt) {
    spit(dir_ / "l.json", l_layout(true));
    // In the notch: the box room only (the L's bounding box holds it too).
    Outcome r = run("$BIN trace l.json --pose 3,1.6,3,0,0,0 --size 8x6 --out t.png");
    EXPECT_EQ(r.status, 0) << r.err;
    // In the arm, looking towards the concave corner: the L only.
    r = run("$BIN render l.json --pose 1,1.6,3.5,-135,0,0 --size 8x6 --out r.png --ids rids.png");
    EXPECT_EQ(r.status, 0) << r.err;
    // On the wall between them: both hold it.
    r = run("$BIN trace l.json --pose 2,1.6,3,0,0,0 --size 8x6 --out t.png");
    expect_refused(r, 1, "--pose: the head is in several rooms (ell, notch); give --room");
}

TEST_F(HostilePrismPose, WithoutTheBoxTheNotchIsInNoRoom) {
    spit(dir_ / "l.json", l_layout(false));
    const Outcome r = run("$BIN trace l.json --pose 3,1.6,3,0,0,0 --size 8x6 --out t.png");
    expect_refused(r, 1, "--pose: the head is in no room; give --room");
    EXPECT_FALSE(fs::exists(dir_ / "t.png"));
    const Outcome in_arm = run("$BIN trace l.json --pose 3,1.6,1,0,0,0 --size 8x6 --out t.png");
    EXPECT_EQ(in_arm.status, 0) << in_arm.err;
}

}  // namespace
}  // namespace impossible::hostile
