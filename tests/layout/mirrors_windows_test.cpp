// Mirrors and windows (layout-format.md, "Portals" and "Mirrors and
// windows"): kind, tint and reflectance, the fields each kind has, pairs of
// one kind, and the face each must lie in.
#include "layout_test_util.hpp"

namespace layout_test {
namespace {

// two_rooms.json plus a mirror in the hall's -z wall and a window pair from
// the hall's -x wall to the annex's +x wall. Each portal is on a line of its
// own, so tests edit one with replace_once.
const char* const kMirror =
    "    { \"id\": \"hall_mirror\", \"kind\": \"mirror\", \"room\": \"hall\", \"center\": [0, 1.5, -2], "
    "\"normal\": [0, 0, 1], \"width\": 1.2, \"height\": 1.8, \"tint\": [0.9, 0.95, 1] }";
const char* const kHallWindow =
    "    { \"id\": \"hall_window\", \"kind\": \"window\", \"room\": \"hall\", \"center\": [-2, 1.5, 0], "
    "\"normal\": [1, 0, 0], \"width\": 1, \"height\": 1, \"tint\": [0.8, 0.9, 1], \"reflectance\": 0.25, "
    "\"target\": \"annex_window\" }";
const char* const kAnnexWindow =
    "    { \"id\": \"annex_window\", \"kind\": \"window\", \"room\": \"annex\", \"center\": [5, 1.3, 0], "
    "\"normal\": [-1, 0, 0], \"width\": 1, \"height\": 1, \"target\": \"hall_window\" }";

std::string with_portals(const std::string& mirror, const std::string& hall_window, const std::string& annex_window) {
    return replace_once(two_rooms(), "\n  ]\n}",
                        ",\n" + mirror + ",\n" + hall_window + ",\n" + annex_window + "\n  ]\n}");
}

std::string mirrors_and_windows() { return with_portals(kMirror, kHallWindow, kAnnexWindow); }

// The text with one thing in one portal changed.
std::string edit(const char* portal, const std::string& from, const std::string& to) {
    const std::string text = mirrors_and_windows();
    return replace_once(text, std::string(portal), replace_once(portal, from, to));
}

TEST(LayoutMirrors, KindsTintsAndReflectanceAreRead) {
    const std::string text = mirrors_and_windows();
    const LoadResult r = load(text);
    ASSERT_TRUE(r.layout.has_value()) << all_messages(r.errors);
    EXPECT_TRUE(r.warnings.empty()) << all_messages(r.warnings);
    const Layout& l = *r.layout;
    ASSERT_EQ(l.portals.size(), 5u);
    // Doors: the default kind, depth and colour fields.
    EXPECT_EQ(l.portals[0].kind, PortalKind::Door);
    EXPECT_EQ(l.portals[0].rect.depth, 0.25);
    EXPECT_EQ(l.portals[1].rect.depth, 0.25);  // the default
    EXPECT_EQ(l.portals[0].target, 1);
    EXPECT_EQ(l.portals[0].tint, glm::dvec3(1.0));
    // The mirror: no target, no box, a hole in the hall's -z wall.
    const Portal& m = l.portals[2];
    EXPECT_EQ(m.kind, PortalKind::Mirror);
    EXPECT_EQ(m.target, -1);
    EXPECT_EQ(m.rect.depth, 0.0);
    EXPECT_EQ(m.tint, glm::dvec3(0.9, 0.95, 1.0));
    EXPECT_EQ(m.hole_face, int(Face::NegZ));
    // The windows: paired, no box, holes in the hall's -x and the annex's +x walls.
    const Portal& a = l.portals[3];
    const Portal& b = l.portals[4];
    EXPECT_EQ(a.kind, PortalKind::Window);
    EXPECT_EQ(b.kind, PortalKind::Window);
    EXPECT_EQ(a.target, 4);
    EXPECT_EQ(b.target, 3);
    EXPECT_EQ(a.rect.depth, 0.0);
    EXPECT_EQ(b.rect.depth, 0.0);
    EXPECT_EQ(a.tint, glm::dvec3(0.8, 0.9, 1.0));
    EXPECT_EQ(a.reflectance, 0.25);
    EXPECT_EQ(b.tint, glm::dvec3(1.0));  // the defaults
    EXPECT_EQ(b.reflectance, 0.1);
    EXPECT_EQ(a.hole_face, int(Face::NegX));
    EXPECT_EQ(b.hole_face, int(Face::PosX));
    EXPECT_STREQ(kind_name(PortalKind::Door), "door");
    EXPECT_STREQ(kind_name(PortalKind::Mirror), "mirror");
    EXPECT_STREQ(kind_name(PortalKind::Window), "window");
}

TEST(LayoutMirrors, AnExplicitDoorIsADoor) {
    const Layout l =
        expect_valid(replace_once(two_rooms(), "\"id\": \"hall_east\",", "\"id\": \"hall_east\", \"kind\": \"door\","));
    EXPECT_EQ(l.portals[0].kind, PortalKind::Door);
    EXPECT_EQ(l.portals[0].rect.depth, 0.25);
}

TEST(LayoutMirrors, AnUnknownKindNamesTheKinds) {
    const std::string text = edit(kMirror, "\"mirror\"", "\"glass\"");
    expect_one_error(text, "\"glass\"",
                     "portals[2].kind: unknown kind \"glass\" (the kinds are \"door\", the default, \"mirror\", "
                     "\"window\" and \"volume\")");
    expect_one_error(edit(kMirror, "\"mirror\"", "\"Mirror\""), "\"Mirror\"",
                     "portals[2].kind: unknown kind \"Mirror\"");
    expect_one_error(edit(kMirror, "\"mirror\"", "2"), "2, \"room\"",
                     "portals[2].kind: must be a string (got a number)");
    // A misspelt key gets a hint.
    expect_error(edit(kMirror, "\"kind\"", "\"knid\""), "\"knid\"",
                 "portals[2].knid: unknown field \"knid\" (did you mean \"kind\"?)");
}

TEST(LayoutMirrors, AFieldTheKindLacksIsAnErrorAtItsKey) {
    const std::string door_tint =
        replace_once(mirrors_and_windows(), "\"depth\": 0.25,", "\"depth\": 0.25, \"tint\": [1, 0, 0],");
    expect_one_error(door_tint, "\"tint\"",
                     "portals[0].tint: a door has no tint (only mirrors and windows tint the light); remove it, or "
                     "set \"kind\" to \"mirror\" or \"window\"");
    const std::string door_reflectance =
        replace_once(mirrors_and_windows(), "\"depth\": 0.25,", "\"depth\": 0.25, \"reflectance\": 0.5,");
    expect_one_error(door_reflectance, "\"reflectance\"",
                     "portals[0].reflectance: a door has no reflectance (only a window's glass reflects); remove "
                     "it, or set \"kind\" to \"window\"");
    expect_one_error(edit(kMirror, "\"tint\"", "\"reflectance\": 0.5, \"tint\""), "\"reflectance\"",
                     "portals[2].reflectance: a mirror has no reflectance (it reflects all the light, times its "
                     "\"tint\"); remove it");
    expect_one_error(edit(kMirror, "\"tint\"", "\"depth\": 0.25, \"tint\""), "\"depth\": 0.25, \"tint\"",
                     "portals[2].depth: a mirror has no depth (it has no box, only its rectangle in a face of its "
                     "room); remove it");
    expect_one_error(edit(kMirror, "\"tint\"", "\"target\": \"hall_east\", \"tint\""),
                     "\"target\": \"hall_east\", \"tint\"",
                     "portals[2].target: a mirror has no target (it reflects its own room); remove it, or set "
                     "\"kind\" to \"window\" to look into the target's room");
    expect_one_error(edit(kAnnexWindow, "\"target\"", "\"depth\": 0.1, \"target\""), "\"depth\": 0.1",
                     "portals[4].depth: a window has no depth (it has no box, only its rectangle in a face of its "
                     "room); remove it");
}

TEST(LayoutMirrors, AWindowNeedsATarget) {
    const std::string text = edit(kHallWindow, ", \"target\": \"annex_window\"", "");
    const LoadResult r = load(text);
    EXPECT_FALSE(r.layout.has_value());
    EXPECT_TRUE(has_error(r, position_of(text, "{ \"id\": \"hall_window\""),
                          "portals[3]: missing required field \"target\" (a window is one of a pair: the id of the "
                          "window whose room it shows)"))
        << all_messages(r.errors);
    EXPECT_EQ(r.errors.size(), 1u) << all_messages(r.errors);
    // A door's missing target says what it is too.
    const std::string door = replace_once(two_rooms(), ",\n      \"target\": \"annex_west\"", "");
    expect_error(door, "{ \"id\": \"hall_east\"",
                 "portals[0]: missing required field \"target\" (the id of the door it leads to)");
}

TEST(LayoutMirrors, PairedPortalsMustBeOfOneKind) {
    // A door (by default) paired with a window: reported once, at the later
    // portal's target when it has no "kind".
    const std::string by_default = edit(kAnnexWindow, "\"kind\": \"window\", ", "");
    expect_one_error(by_default, "\"hall_window\" }",
                     "portals[4].target: a door cannot be paired with the window \"hall_window\" (paired portals "
                     "must be of the same kind; make both doors or both windows)");
    // At its "kind" when it has one.
    const std::string explicit_kind = edit(kAnnexWindow, "\"kind\": \"window\"", "\"kind\": \"door\"");
    expect_one_error(explicit_kind, "\"door\"",
                     "portals[4].kind: a door cannot be paired with the window \"hall_window\"");
    // The earlier portal is the door: still reported at the later one.
    std::string window_second =
        replace_once(two_rooms(), "\"id\": \"annex_west\",", "\"id\": \"annex_west\", \"kind\": \"window\",");
    const LoadResult r = load(window_second);
    EXPECT_TRUE(has_error(r, position_of(window_second, "\"window\""),
                          "portals[1].kind: a window cannot be paired with the door \"hall_east\""))
        << all_messages(r.errors);
}

TEST(LayoutMirrors, NothingMayTargetAMirror) {
    // A door naming a mirror: the mirror names nothing back.
    const std::string text =
        replace_once(mirrors_and_windows(), "\"target\": \"annex_west\"", "\"target\": \"hall_mirror\"");
    expect_error(text, "\"hall_mirror\" }",
                 "portals[0].target: \"hall_mirror\" is a mirror, which has no partner (it reflects its own "
                 "room); a door must target a door that names it back");
    // A window naming a mirror.
    const std::string window = edit(kAnnexWindow, "\"target\": \"hall_window\"", "\"target\": \"hall_mirror\"");
    expect_error(window, "\"hall_mirror\" }",
                 "portals[4].target: \"hall_mirror\" is a mirror, which has no partner (it reflects its own "
                 "room); a window must target a window that names it back");
}

TEST(LayoutMirrors, TintAndReflectanceAreIn0To1) {
    expect_one_error(edit(kMirror, "[0.9, 0.95, 1]", "[1.2, 0.95, 1]"), "1.2, 0.95",
                     "portals[2].tint[0]: colour component 1.2 is outside 0..1");
    expect_one_error(edit(kHallWindow, "[0.8, 0.9, 1]", "[0.8, -0.1, 1]"), "-0.1, 1]",
                     "portals[3].tint[1]: colour component -0.1 is outside 0..1");
    expect_one_error(edit(kHallWindow, "[0.8, 0.9, 1]", "[0.8, 0.9]"), "[0.8, 0.9]",
                     "portals[3].tint: must be an array of 3 numbers [r, g, b] (got an array of 2)");
    expect_one_error(edit(kHallWindow, "0.25", "1.5"), "1.5, \"target\"",
                     "portals[3].reflectance: must be in 0..1 (got 1.5)");
    expect_one_error(edit(kHallWindow, "0.25", "-0.01"), "-0.01,",
                     "portals[3].reflectance: must be in 0..1 (got -0.01)");
    expect_one_error(edit(kHallWindow, "0.25", "\"high\""), "\"high\"",
                     "portals[3].reflectance: must be a number (got a string)");
    // The ends are allowed: a clear pane, and one that only reflects.
    EXPECT_EQ(expect_valid(edit(kHallWindow, "0.25", "0")).portals[3].reflectance, 0.0);
    EXPECT_EQ(expect_valid(edit(kHallWindow, "0.25", "1")).portals[3].reflectance, 1.0);
    EXPECT_EQ(expect_valid(edit(kMirror, "[0.9, 0.95, 1]", "[0, 0, 0]")).portals[2].tint, glm::dvec3(0.0));
    // JSON has no NaN or infinity: a syntax error where it stands.
    for (const char* bad : {"NaN", "nan", "Infinity", "-Infinity", "1e400"}) {
        const std::string text = edit(kHallWindow, "0.25", bad);
        const LoadResult r = load(text);
        EXPECT_FALSE(r.layout.has_value()) << bad;
        ASSERT_EQ(r.errors.size(), 1u) << bad << "\n" << all_messages(r.errors);
        const Pos want = position_of(text, std::string(bad) + ",");
        EXPECT_EQ(r.errors[0].line, want.line) << bad << ": " << r.errors[0].str();
        EXPECT_EQ(r.errors[0].column, want.column) << bad << ": " << r.errors[0].str();
    }
}

TEST(LayoutMirrors, AMirrorOrWindowMustLieInAFaceOfItsRoom) {
    // 0.3 m in front of the -z wall.
    expect_one_error(edit(kMirror, "[0, 1.5, -2]", "[0, 1.5, -1.7]"), "[0, 1.5, -1.7]",
                     "portals[2].center: a mirror must lie in a face of its own room \"hall\" (within 0.0001 m of "
                     "the face's plane, inside the face), but this one stands free: a corner is 0.3 m from the -z "
                     "face (z = -2), the face its normal looks away from; move it into that face");
    // In the plane of the -z face but beside it.
    expect_one_error(edit(kMirror, "[0, 1.5, -2]", "[4, 1.5, -2]"), "[4, 1.5, -2]",
                     "portals[2].center: a mirror must lie in a face of its own room \"hall\" (within 0.0001 m of "
                     "the face's plane, inside the face), but this one stands free: it lies in the plane of the -z "
                     "face (z = -2) but outside that face; move it inside the face");
    // In the face, facing out of the room.
    expect_one_error(edit(kMirror, "\"normal\": [0, 0, 1]", "\"normal\": [0, 0, -1]"), "[0, 1.5, -2]",
                     "portals[2].center: a mirror must lie in a face of its own room \"hall\" (within 0.0001 m of "
                     "the face's plane, inside the face), but this one stands free: it lies in the plane of the -z "
                     "face (z = -2) but its normal points out of the room; turn the normal around");
    // Tilted 45°: no face is the right one.
    expect_one_error(edit(kMirror, "\"normal\": [0, 0, 1]", "\"normal\": [0.7071068, 0, 0.7071068]"), "[0, 1.5, -2]",
                     "portals[2].center: a mirror must lie in a face of its own room \"hall\" (within 0.0001 m of "
                     "the face's plane, inside the face), but this one stands free: a corner is ");
    // A window in the middle of the annex.
    expect_one_error(edit(kAnnexWindow, "[5, 1.3, 0]", "[3.5, 1.3, 0]"), "[3.5, 1.3, 0]",
                     "portals[4].center: a window must lie in a face of its own room \"annex\" (within 0.0001 m "
                     "of the face's plane, inside the face), but this one stands free: a corner is 1.5 m from the "
                     "+x face (x = 5)");
    // Partly covering is the hole rule's own error, for every kind, and only that.
    expect_one_error(edit(kMirror, "[0, 1.5, -2]", "[2, 1.5, -2]"), "[2, 1.5, -2]",
                     "portals[2].center: the rectangle lies in the plane of the -z face of room \"hall\" but is only "
                     "partly inside that face (a mirror must lie wholly inside a face of its room, making a hole; "
                     "move it inside)");
    // A free-standing door is fine.
    EXPECT_EQ(expect_valid(replace_once(two_rooms(), "\"center\": [2.0, 1.1, 0.0], \"normal\": [-1, 0, 0]",
                                        "\"center\": [1.5, 1.1, 0.0], \"normal\": [-1, 0, 0]"))
                  .portals[0]
                  .hole_face,
              -1);
}

TEST(LayoutMirrors, MirrorsAndWindowsInFloorsAndCeilings) {
    const std::string floor = edit(kMirror, "\"center\": [0, 1.5, -2], \"normal\": [0, 0, 1]",
                                   "\"center\": [0, 0, 0.5], \"normal\": [0, 1, 0], \"up\": [0, 0, -1]");
    EXPECT_EQ(expect_valid(floor).portals[2].hole_face, int(Face::Floor));
    const std::string ceiling = edit(kAnnexWindow, "\"center\": [5, 1.3, 0], \"normal\": [-1, 0, 0]",
                                     "\"center\": [3.5, 2.6, 0], \"normal\": [0, -1, 0], \"up\": [0, 0, 1]");
    EXPECT_EQ(expect_valid(ceiling).portals[4].hole_face, int(Face::Ceiling));
}

TEST(LayoutMirrors, AWindowPairMayShareARoom) {
    // Two windows on two walls of one room: the room seen from the other side.
    const std::string text = edit(kAnnexWindow, "\"room\": \"annex\", \"center\": [5, 1.3, 0], \"normal\": [-1, 0, 0]",
                                  "\"room\": \"hall\", \"center\": [0, 1.5, 2], \"normal\": [0, 0, -1]");
    const Layout l = expect_valid(text);
    EXPECT_EQ(l.portals[3].room, l.portals[4].room);
    EXPECT_EQ(l.portals[4].hole_face, int(Face::PosZ));
}

TEST(LayoutMirrors, AMirrorsHoleMustNotOverlapADoorsHole) {
    // The mirror moved into the hall's +x wall, over the doorway to the annex.
    const std::string text = edit(kMirror, "\"center\": [0, 1.5, -2], \"normal\": [0, 0, 1]",
                                  "\"center\": [2, 1.5, 0.5], \"normal\": [-1, 0, 0]");
    expect_one_error(text, "[2, 1.5, 0.5]",
                     "portals[2].center: its hole in the +x face of room \"hall\" overlaps the hole of portal "
                     "\"hall_east\" (portals[0])");
}

TEST(LayoutMirrors, ADoorStillWarnsOfAShallowBox) {
    const LoadResult r = load(replace_once(mirrors_and_windows(), "\"depth\": 0.25", "\"depth\": 0.02"));
    EXPECT_TRUE(r.layout.has_value()) << all_messages(r.errors);
    ASSERT_EQ(r.warnings.size(), 1u) << all_messages(r.warnings);
    EXPECT_EQ(r.warnings[0].message.rfind("portals[0].depth: the box is 0.02 m deep", 0), 0u);
}

TEST(LayoutMirrors, ManyErrorsAtOnce) {
    // Each wrong field once, in file order, none hiding another.
    std::string text = with_portals(replace_once(replace_once(kMirror, "\"tint\"", "\"reflectance\": 0.3, \"tint\""),
                                                 "[0.9, 0.95, 1]", "[2, 0, 0]"),
                                    replace_once(kHallWindow, "0.25", "7"),
                                    replace_once(kAnnexWindow, "\"target\"", "\"depth\": 1, \"target\""));
    const LoadResult r = load(text);
    EXPECT_FALSE(r.layout.has_value());
    ASSERT_EQ(r.errors.size(), 4u) << all_messages(r.errors);
    EXPECT_EQ(r.errors[0].message.rfind("portals[2].reflectance: a mirror has no reflectance", 0), 0u);
    EXPECT_EQ(r.errors[1].message.rfind("portals[2].tint[0]: colour component 2 is outside 0..1", 0), 0u);
    EXPECT_EQ(r.errors[2].message.rfind("portals[3].reflectance: must be in 0..1 (got 7)", 0), 0u);
    EXPECT_EQ(r.errors[3].message.rfind("portals[4].depth: a window has no depth", 0), 0u);
    for (const Diagnostic& d : r.errors) {
        EXPECT_EQ(d.file, "t.json");
        EXPECT_GT(d.line, 0);
        EXPECT_GT(d.column, 0);
    }
}

TEST(LayoutMirrors, TheSummaryCountsEachKind) {
    const Layout l = expect_valid(mirrors_and_windows());
    const Summary s = summarize(l);
    EXPECT_EQ(s.portals, 5);
    EXPECT_EQ(s.pairs, 2);
    EXPECT_EQ(s.door_pairs, 1);
    EXPECT_EQ(s.window_pairs, 1);
    EXPECT_EQ(s.mirrors, 1);
    const std::string text = summary_text(l, s);
    EXPECT_NE(text.find("portals: 5\npairs: 2\ndoor pairs: 1\nwindow pairs: 1\nmirrors: 1\n"), std::string::npos)
        << text;
    // Without mirrors and windows the summary is as it always was.
    const Layout doors = expect_valid(two_rooms());
    const std::string plain = summary_text(doors, summarize(doors));
    EXPECT_EQ(plain.find("door pairs"), std::string::npos) << plain;
    EXPECT_EQ(plain.find("mirrors"), std::string::npos) << plain;
    EXPECT_NE(plain.find("portals: 2\npairs: 1\nplay area: "), std::string::npos) << plain;
    // A mirror alone: no pairs at all.
    const std::string mirror_only =
        replace_once(two_rooms().substr(0, two_rooms().find(",\n  \"portals\"")) + "\n}\n", "\n}\n",
                     ",\n  \"portals\": [\n" + std::string(kMirror) + "\n  ]\n}\n");
    const Layout m = expect_valid(mirror_only);
    const Summary ms = summarize(m);
    EXPECT_EQ(ms.portals, 1);
    EXPECT_EQ(ms.pairs, 0);
    EXPECT_EQ(ms.mirrors, 1);
    EXPECT_NE(summary_text(m, ms).find("pairs: 0\ndoor pairs: 0\nwindow pairs: 0\nmirrors: 1\n"), std::string::npos);
}

}  // namespace
}  // namespace layout_test
