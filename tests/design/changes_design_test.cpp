// The designer's tools on layouts with changes (issue 40, item 5): validate
// lists the changes and the rooms each makes reachable, plan draws each
// change's pairs dashed with its id, tour walks with the changes, and the
// rooms its poses visit are checked by walking them again with
// changes::ChangeWalker (the seen test on render's default eyes) and after
// a round trip through the path file's text.
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "changes/change_walker.hpp"
#include "design/path_text.hpp"
#include "design/plan.hpp"
#include "design/report.hpp"
#include "design/report_changes.hpp"
#include "design/tour.hpp"
#include "design_test_util.hpp"
#include "layout/path_file.hpp"

namespace design_test {
namespace {

std::string door(const std::string& id, const std::string& room, double x, double z, double nz,
                 const std::string& target) {
    return "{ \"id\": \"" + id + "\", \"room\": \"" + room + "\", \"center\": [" + std::to_string(x) + ", 1.05, " +
           std::to_string(z) + "], \"normal\": [0, 0, " + std::to_string(nz) +
           "], \"width\": 0.9, \"height\": 2.1, \"target\": \"" + target + "\" }";
}

// The hall (z 0..2) and the study (z -2..0) joined by two door pairs at
// x = -1 and x = 1; the vault and the attic, east of them, joined only to
// each other. The change "open", `when` as given, pairs the study's east
// door with the vault's: the vault is reachable only after it, the attic
// never (its door is closed by it).
layout::Layout vault_layout(const std::string& when, const std::string& earlier = "") {
    const std::string text =
        R"({ "format": "impossible-layout", "version": 1,
  "play_area": { "min": [-2.5, -2.5], "max": [5.5, 2.5] },
  "start": { "room": "hall", "position": [-1, 1.6, 1.5] },
  "rooms": [)" +
        room("hall", -2, 0, 2, 2) + ",\n" + room("study", -2, -2, 2, 0) + ",\n" + room("vault", 3, 0, 5, 2) + ",\n" +
        room("attic", 3, -2, 5, 0) + "],\n\"portals\": [" + door("hall_west", "hall", -1, 0, 1, "study_west") + ",\n" +
        door("study_west", "study", -1, 0, -1, "hall_west") + ",\n" + door("hall_east", "hall", 1, 0, 1, "study_east") +
        ",\n" + door("study_east", "study", 1, 0, -1, "hall_east") + ",\n" +
        door("vault_door", "vault", 4, 0, 1, "attic_door") + ",\n" +
        door("attic_door", "attic", 4, 0, -1, "vault_door") + "],\n" + R"("changes": [ )" + earlier +
        R"( { "id": "open", "when": )" + when + R"(, "pairs": [["study_east", "vault_door"]] } ] })";
    const layout::LoadResult r = layout::load_layout_text(text, "vault.json", ".");
    std::string errors;
    for (const auto& d : r.errors) errors += d.str() + "\n";
    EXPECT_TRUE(r.layout.has_value()) << errors << text;
    return r.layout.value_or(layout::Layout{});
}

std::vector<std::string> room_ids(const layout::Layout& l, const std::vector<int>& rooms) {
    std::vector<std::string> ids;
    for (const int r : rooms) ids.push_back(l.rooms[static_cast<std::size_t>(r)].id);
    std::sort(ids.begin(), ids.end());
    return ids;
}

TEST(ChangesReport, DoorSwapListsTheChangeItsPairsAndDoors) {
    const layout::Layout l = load_file("door_swap.json");
    const design::Report r = design::make_report(l);
    ASSERT_EQ(r.changes.changes.size(), 1u);
    EXPECT_TRUE(r.changes.changes[0].can_happen);
    EXPECT_TRUE(r.changes.changes[0].makes_reachable.empty());  // the garden was reachable before
    const std::string text = design::report_text(l, r);
    EXPECT_NE(text.find("reachable rooms: 3 of 3\n"), std::string::npos) << text;
    EXPECT_NE(text.find("changes: 1\n  swap (when enter study): pairs study_left/garden_door; makes reachable: none\n"),
              std::string::npos)
        << text;
    const nlohmann::ordered_json j = design::report_json(l, r, {});
    ASSERT_EQ(j["changes"].size(), 1u);
    EXPECT_EQ(j["changes"][0]["id"], "swap");
    EXPECT_EQ(j["changes"][0]["when"], nlohmann::ordered_json({{"enter", "study"}}));
    EXPECT_EQ(j["changes"][0]["pairs"], nlohmann::json::parse(R"([["study_left", "garden_door"]])"));
    EXPECT_EQ(j["changes"][0]["affected_doors"],
              nlohmann::json::parse(R"(["hall_door", "study_left", "study_right", "garden_door"])"));
    EXPECT_EQ(j["changes"][0]["can_happen"], true);
    EXPECT_TRUE(j["changes"][0]["makes_reachable"].empty());
}

TEST(ChangesReport, ARoomReachableOnlyAfterAChangeIsReachableAndSaysSo) {
    const layout::Layout l = vault_layout(R"({ "enter": "study", "time": 2.5 })");
    const design::Report r = design::make_report(l);
    EXPECT_EQ(room_ids(l, r.changes.changes[0].makes_reachable), std::vector<std::string>{"vault"});
    EXPECT_EQ(room_ids(l, r.unreachable), std::vector<std::string>{"attic"});
    const std::string text = design::report_text(l, r);
    EXPECT_NE(text.find("reachable rooms: 3 of 4 (1 only after a change: vault after open)\n"), std::string::npos)
        << text;
    EXPECT_NE(text.find("unreachable rooms: attic\n"), std::string::npos) << text;
    EXPECT_NE(text.find("  open (when enter study, time 2.5 s): pairs study_east/vault_door; makes reachable: vault\n"),
              std::string::npos)
        << text;
    for (const std::string& f : r.findings) EXPECT_EQ(f.find("\"vault\""), std::string::npos) << f;
    const nlohmann::ordered_json j = design::report_json(l, r, {});
    EXPECT_EQ(j["changes"][0]["makes_reachable"], nlohmann::json::parse(R"(["vault"])"));
    EXPECT_EQ(j["changes"][0]["when"]["time"], 2.5);
    EXPECT_EQ(j["rooms"][2]["id"], "vault");
    EXPECT_EQ(j["rooms"][2]["reachable"], true);
    EXPECT_EQ(j["rooms"][2]["reachable_after_change"], "open");
    EXPECT_FALSE(j["rooms"][3].contains("reachable_after_change"));
    EXPECT_EQ(j["unreachable_rooms"], nlohmann::json::parse(R"(["attic"])"));
}

TEST(ChangesReport, AChangeWhoseRoomIsNeverReachedMakesNothingReachable) {
    const layout::Layout l = vault_layout(R"({ "enter": "attic" })");
    const design::Report r = design::make_report(l);
    EXPECT_FALSE(r.changes.changes[0].can_happen);
    EXPECT_TRUE(r.changes.changes[0].makes_reachable.empty());
    EXPECT_EQ(room_ids(l, r.unreachable), (std::vector<std::string>{"attic", "vault"}));
    EXPECT_NE(design::report_text(l, r).find("makes reachable: none; can never happen\n"), std::string::npos);
}

TEST(ChangesReport, LayoutsWithoutChangesSayNothingNew) {
    const layout::Layout l = load_file("four_rooms.json");
    const design::Report r = design::make_report(l);
    EXPECT_EQ(design::report_text(l, r).find("changes"), std::string::npos);
    EXPECT_FALSE(design::report_json(l, r, {}).contains("changes"));
}

TEST(ChangesPlan, DrawsEachPairDashedWithTheChangesId) {
    const layout::Layout l = load_file("door_swap.json");
    const design::Report r = design::make_report(l);
    const design::Drawing d = design::plan_drawing(l, r, {});
    int dashed = 0, labels = 0;
    for (const design::PlanShape& s : d.shapes) {
        if (s.group != "changes") continue;
        EXPECT_EQ(s.name, "swap: study_left/garden_door");
        if (s.kind == design::PlanShape::Kind::Stroke && s.dashed) {
            ++dashed;
            ASSERT_EQ(s.points.size(), 2u);  // from the study's left door to the garden's door
            EXPECT_NEAR(s.points[0].x, -1.0, 1e-9);
            EXPECT_NEAR(s.points[1].x, 1.0, 1e-9);
        }
        if (s.kind == design::PlanShape::Kind::Text) labels += s.text == "swap";
    }
    EXPECT_EQ(dashed, 1);
    EXPECT_EQ(labels, 1);
    const bool legend = std::any_of(d.legend.begin(), d.legend.end(), [](const design::LegendEntry& e) {
        return e.sample == design::LegendEntry::Sample::Dashed && e.text.find("change") != std::string::npos;
    });
    EXPECT_TRUE(legend);
    const std::string svg = design::plan_svg(d, design::plan_scale(d, 800));
    const std::size_t group = svg.find("<g id=\"changes\">");
    ASSERT_NE(group, std::string::npos);
    const std::string changes = svg.substr(group, svg.find("</g>", group) - group);
    EXPECT_NE(changes.find("stroke-dasharray"), std::string::npos) << changes;
    EXPECT_NE(changes.find(">swap</text>"), std::string::npos) << changes;
    EXPECT_NE(svg.find("a change's new pair"), std::string::npos);
}

// The PNG draws the pair too: the change's purple where the SVG has its
// dashes, and not without the "changes" shapes.
TEST(ChangesPlan, ThePngDrawsThePairInTheChangesColour) {
    const layout::Layout l = load_file("door_swap.json");
    design::Drawing d = design::plan_drawing(l, design::make_report(l), {});
    const double k = design::plan_scale(d, 600);
    const auto purple = [](const image::Pixels& p) {
        std::size_t n = 0;
        for (std::size_t i = 0; i + 2 < p.data.size(); i += static_cast<std::size_t>(p.channels))
            n += std::abs(p.data[i] - 107) < 12 && std::abs(p.data[i + 1] - 31) < 12 &&
                 std::abs(p.data[i + 2] - 173) < 12;
        return n;
    };
    const std::size_t with = purple(design::plan_raster(d, k));
    std::erase_if(d.shapes, [](const design::PlanShape& s) { return s.group == "changes"; });
    std::erase_if(d.legend, [](const design::LegendEntry& e) { return e.text.find("change") != std::string::npos; });
    const std::size_t without = purple(design::plan_raster(d, k));
    EXPECT_GT(with, 200u);  // the dashes, the dots and the label: hundreds of pixels
    EXPECT_LT(without, with / 10);
}

TEST(ChangesPlan, CoincidentDoorsGetADashedRingAndLaterRoomsAreNotCalledUnreachable) {
    const layout::Layout l = load_file("rerouted_corridor.json");
    const design::Report r = design::make_report(l);
    const design::Drawing d = design::plan_drawing(l, r, {});
    const auto ring = std::find_if(d.shapes.begin(), d.shapes.end(), [](const design::PlanShape& s) {
        return s.group == "changes" && s.kind == design::PlanShape::Kind::Stroke;
    });
    ASSERT_NE(ring, d.shapes.end());
    EXPECT_TRUE(ring->dashed && ring->closed);
    const layout::Layout v = vault_layout(R"({ "enter": "study" })");
    const design::Drawing dv = design::plan_drawing(v, design::make_report(v), {});
    std::vector<std::string> labels;
    for (const design::PlanShape& s : dv.shapes)
        if (s.group == "labels") labels.push_back(s.text);
    EXPECT_NE(std::find(labels.begin(), labels.end(), "vault (after open)"), labels.end());
    EXPECT_NE(std::find(labels.begin(), labels.end(), "attic (unreachable)"), labels.end());
}

// The tour's poses walked again, after a round trip through the path file.
changes::ChangeWalkResult rewalk(const layout::Layout& l, const design::Tour& t) {
    const std::string text = design::path_text(t.poses, "test");
    std::istringstream in(text);
    const layout::PathFile read = layout::read_path_stream(in, "tour.txt");
    EXPECT_TRUE(read.has_value());
    const std::vector<math::HeadPose> poses = read.has_value() ? read.value() : std::vector<math::HeadPose>{};
    EXPECT_EQ(poses.size(), t.poses.size());
    return changes::walk_with_changes(l, poses);
}

TEST(ChangesTour, DoorSwapVisitsHallStudyAndGardenAndMakesTheSwap) {
    const layout::Layout l = load_file("door_swap.json");
    const auto t = design::plan_tour(l);
    ASSERT_TRUE(t.has_value()) << t.error();
    EXPECT_EQ(room_ids(l, t->visited), (std::vector<std::string>{"garden", "hall", "study"}));
    EXPECT_TRUE(t->missed.empty());
    ASSERT_EQ(t->changes, std::vector<int>{0});
    const changes::ChangeWalkResult w = rewalk(l, *t);
    EXPECT_EQ(room_ids(l, w.rooms), (std::vector<std::string>{"garden", "hall", "study"}));
    EXPECT_EQ(w.changes, std::vector<int>{0});
    ASSERT_FALSE(t->notes.empty());
    EXPECT_EQ(t->notes[0].text,
              "change swap is made here, in study (frame " + std::to_string(w.change_frames[0]) + ")");
    EXPECT_EQ(t->notes[0].pose, static_cast<std::size_t>(w.change_frames[0]));
}

TEST(ChangesTour, ReroutedCorridorVisitsAllFiveRooms) {
    const layout::Layout l = load_file("rerouted_corridor.json");
    const auto t = design::plan_tour(l);
    ASSERT_TRUE(t.has_value()) << t.error();
    const std::vector<std::string> all{"blue_corridor", "gallery", "library", "lobby", "red_corridor"};
    EXPECT_EQ(room_ids(l, t->visited), all);
    // In order: the gallery, whose entry arms the change, last; each room by
    // the way planned from where the head is (none by a door passed by accident).
    std::vector<std::string> order;
    for (const int r : t->visited) order.push_back(l.rooms[static_cast<std::size_t>(r)].id);
    EXPECT_EQ(order, (std::vector<std::string>{"lobby", "blue_corridor", "red_corridor", "library", "gallery"}));
    // blue and back, red, library and back, back to the lobby, blue again, gallery
    EXPECT_EQ(t->teleports, 8);
    const changes::ChangeWalkResult w = rewalk(l, *t);
    EXPECT_EQ(room_ids(l, w.rooms), all);
    EXPECT_EQ(w.changes, std::vector<int>{0});
}

TEST(ChangesTour, WaitsInTheStudyForTheChangeThatOpensTheVault) {
    const layout::Layout l = vault_layout(R"({ "enter": "study", "time": 20 })");
    const auto t = design::plan_tour(l);
    ASSERT_TRUE(t.has_value()) << t.error();
    EXPECT_EQ(room_ids(l, t->visited), (std::vector<std::string>{"hall", "study", "vault"}));
    const auto wait = std::find_if(t->notes.begin(), t->notes.end(),
                                   [](const design::TourNote& n) { return n.text.rfind("waits in study", 0) == 0; });
    ASSERT_NE(wait, t->notes.end());
    EXPECT_EQ(wait->text, "waits in study for change open: stands still until 20 s, then turns away from its doors");
    const changes::ChangeWalkResult w = rewalk(l, *t);
    EXPECT_EQ(room_ids(l, w.rooms), (std::vector<std::string>{"hall", "study", "vault"}));
    ASSERT_EQ(w.changes, std::vector<int>{0});
    EXPECT_GE(w.change_frames[0], 20 * 90);  // not before its time
}

// The study's north door faces whoever comes in from the hall: the change
// "open" (pairing it with the attic's door) waits until the tour turns
// away from it in the study.
layout::Layout north_door_layout() {
    const std::string text = R"({ "format": "impossible-layout", "version": 1,
  "play_area": { "min": [-2.5, -2.5], "max": [5.5, 2.5] },
  "start": { "room": "hall", "position": [-1, 1.6, 1.5] },
  "rooms": [)" + room("hall", -2, 0, 2, 2) +
                             ",\n" + room("study", -2, -2, 2, 0) + ",\n" + room("attic", 3, -2, 5, 0) +
                             "],\n\"portals\": [" + door("hall_west", "hall", -1, 0, 1, "study_west") + ",\n" +
                             door("study_west", "study", -1, 0, -1, "hall_west") + ",\n" +
                             door("study_north", "study", 0, -2, 1, "hall_back") + ",\n" +
                             door("hall_back", "hall", 0, 2, -1, "study_north") + ",\n" +
                             door("attic_door", "attic", 4, -2, 1, "attic_back") + ",\n" +
                             door("attic_back", "attic", 4, 0, -1, "attic_door") + "],\n" +
                             R"("changes": [ { "id": "open", "when": { "enter": "study" },)" +
                             R"( "pairs": [["study_north", "attic_door"]] } ] })";
    const layout::LoadResult r = layout::load_layout_text(text, "north.json", ".");
    std::string errors;
    for (const auto& d : r.errors) errors += d.str() + "\n";
    EXPECT_TRUE(r.layout.has_value()) << errors << text;
    return r.layout.value_or(layout::Layout{});
}

TEST(ChangesTour, TurnsInTheStudyUntilItsNorthDoorIsOutOfSight) {
    const layout::Layout l = north_door_layout();
    const auto t = design::plan_tour(l);
    ASSERT_TRUE(t.has_value()) << t.error();
    EXPECT_EQ(room_ids(l, t->visited), (std::vector<std::string>{"attic", "hall", "study"}));
    const auto wait = std::find_if(t->notes.begin(), t->notes.end(), [](const design::TourNote& n) {
        return n.text == "waits in study for change open: turns away from its doors";
    });
    ASSERT_NE(wait, t->notes.end());
    const changes::ChangeWalkResult w = rewalk(l, *t);
    EXPECT_EQ(room_ids(l, w.rooms), (std::vector<std::string>{"attic", "hall", "study"}));
    ASSERT_EQ(w.changes, std::vector<int>{0});
    // Made while turning on the spot: after the note, where it stood, facing elsewhere.
    const std::size_t made = static_cast<std::size_t>(w.change_frames[0]);
    ASSERT_GT(made, wait->pose);
    EXPECT_EQ(t->poses[made].position, t->poses[wait->pose - 1].position);
    EXPECT_GT(std::abs(std::remainder(t->poses[made].yaw_deg - t->poses[wait->pose - 1].yaw_deg, 360.0)), 10.0);
}

// As north_door_layout, but the attic is also reached through the hall's
// east door: the tour visits it first (the study, whose entry arms the
// change, comes last), and then, every room visited, turns in the study
// until the armed change is made.
TEST(ChangesTour, EndsByTurningUntilAnArmedChangeIsMade) {
    const std::string text = R"({ "format": "impossible-layout", "version": 1,
  "play_area": { "min": [-2.5, -2.5], "max": [5.5, 2.5] },
  "start": { "room": "hall", "position": [-1, 1.6, 1.5] },
  "rooms": [)" + room("hall", -2, 0, 2, 2) +
                             ",\n" + room("study", -2, -2, 2, 0) + ",\n" + room("attic", 3, -2, 5, 0) +
                             "],\n\"portals\": [" + door("hall_west", "hall", -1, 0, 1, "study_west") + ",\n" +
                             door("study_west", "study", -1, 0, -1, "hall_west") + ",\n" +
                             door("study_north", "study", 0, -2, 1, "hall_back") + ",\n" +
                             door("hall_back", "hall", 0, 2, -1, "study_north") + ",\n" +
                             door("hall_east", "hall", 1, 0, 1, "attic_back") + ",\n" +
                             door("attic_back", "attic", 4, 0, -1, "hall_east") + ",\n" +
                             door("attic_door", "attic", 4, -2, 1, "attic_side") + ",\n" +
                             R"({ "id": "attic_side", "room": "attic", "center": [3, 1.05, -1], "normal": [1, 0, 0],)" +
                             R"( "width": 0.9, "height": 2.1, "target": "attic_door" }],)" +
                             R"("changes": [ { "id": "open", "when": { "enter": "study" },)" +
                             R"( "pairs": [["study_north", "attic_door"]] } ] })";
    const layout::LoadResult loaded = layout::load_layout_text(text, "settle.json", ".");
    ASSERT_TRUE(loaded.layout.has_value()) << (loaded.errors.empty() ? "" : loaded.errors[0].str());
    const layout::Layout& l = *loaded.layout;
    const auto t = design::plan_tour(l);
    ASSERT_TRUE(t.has_value()) << t.error();
    ASSERT_EQ(t->visited.size(), 3u);
    EXPECT_EQ(l.rooms[static_cast<std::size_t>(t->visited.back())].id, "study");  // the arming room last
    ASSERT_FALSE(t->notes.empty());
    EXPECT_EQ(t->notes[0].text, "waits in study for change open: turns away from its doors");
    const changes::ChangeWalkResult w = rewalk(l, *t);
    ASSERT_EQ(w.changes, std::vector<int>{0});
    EXPECT_GT(static_cast<std::size_t>(w.change_frames[0]), t->notes[0].pose);
}

TEST(ChangesTour, AChangeAfterOneThatCanNeverHappenCannotHappenEither) {
    // "late" swaps the two west doors (hall's with the study's east door and
    // back again) after more time than a tour waits; "open" waits for it.
    const layout::Layout l = vault_layout(R"({ "after": "late", "enter": "study" })",
                                          R"({ "id": "late", "when": { "enter": "study", "time": 100000 },)"
                                          R"( "pairs": [["hall_west", "study_east"], ["hall_east", "study_west"]] },)");
    EXPECT_TRUE(design::make_report(l).changes.changes[1].can_happen);  // as far as validate can tell
    const auto t = design::plan_tour(l);
    ASSERT_FALSE(t.has_value());
    EXPECT_EQ(t.error(),
              "the tour cannot visit room \"vault\": it needs change \"open\", which can never happen on its route: it "
              "waits for change \"late\", which cannot happen on the tour's route");
}

TEST(ChangesTour, FailsNamingTheChangeAndTheRoomWhenTheChangeCanNeverHappen) {
    const layout::Layout l = vault_layout(R"({ "enter": "study", "time": 100000 })");
    const auto t = design::plan_tour(l);
    ASSERT_FALSE(t.has_value());
    EXPECT_EQ(
        t.error(),
        "the tour cannot visit room \"vault\": it needs change \"open\", which can never happen on its route: its "
        "time, 100000 s, is more than 300 s after the tour comes to room \"study\"");
}

}  // namespace
}  // namespace design_test
