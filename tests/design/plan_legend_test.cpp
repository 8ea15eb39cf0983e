// The plan's legend, names, lamps and moving props' paths (issue 38): the
// SVG and the PNG show the same things, text included, and overlapping
// rooms have colours and hatching that can be told apart.
#include <algorithm>
#include <cmath>

#include "design/plan.hpp"
#include "design/report.hpp"
#include "design_test_util.hpp"

namespace design_test {
namespace {

bool has_group(const design::Drawing& d, const std::string& group) {
    return std::any_of(d.shapes.begin(), d.shapes.end(), [&](const design::PlanShape& s) { return s.group == group; });
}

bool has_entry(const design::Drawing& d, const std::string& text) {
    return std::any_of(d.legend.begin(), d.legend.end(), [&](const design::LegendEntry& e) { return e.text == text; });
}

// Pixels darker than 0.6 (text and lines, not translucent floors) in rows y0..y1.
int dark_pixels(const image::Pixels& image, int y0, int y1) {
    int n = 0;
    for (int y = std::max(0, y0); y < std::min(image.height, y1); ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = &image.data[(static_cast<std::size_t>(y) * image.width + x) * 3];
            n += p[0] + p[1] + p[2] < 3 * 153;
        }
    return n;
}

TEST(PlanLegend, ThreeOverlappingRoomsHaveColoursAndHatchingOfTheirOwn) {
    const layout::Layout l =
        load("", "a", room("a", 0, 0, 4, 4) + "," + room("b", 1, 1, 5, 5) + "," + room("c", 2, 0, 6, 4), "");
    const design::Drawing d = design::plan_drawing(l, design::make_report(l), {});
    ASSERT_GE(d.legend.size(), 3u);
    for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j) {
            const design::Rgba a = d.legend[i].line, b = d.legend[j].line;
            // Far apart in RGB (the old golden-ratio hues at one saturation came within 0.3).
            EXPECT_GT(std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b), 0.5) << i << " " << j;
            EXPECT_NE(d.legend[i].hatch, d.legend[j].hatch);
        }
    EXPECT_EQ(d.legend[0].text, "a");
    EXPECT_TRUE(has_group(d, "hatching"));
    int hatched_a = 0;
    for (const design::PlanShape& s : d.shapes) hatched_a += s.group == "hatching" && s.name == "a";
    EXPECT_GT(hatched_a, 10);  // a 4 m room, lines 0.2 m apart
}

TEST(PlanLegend, LampsAndMovingPropsPathsAreDrawnAndListed) {
    const layout::Layout lamps = load_file("lamp_hall.json");
    const design::Drawing d = design::plan_drawing(lamps, design::make_report(lamps), {});
    EXPECT_TRUE(has_group(d, "lights"));
    EXPECT_TRUE(has_entry(d, "lamp"));
    const std::string svg = design::plan_svg(d, 50.0);
    EXPECT_NE(svg.find("<g id=\"lights\">"), std::string::npos);
    EXPECT_NE(svg.find(">lamp</text>"), std::string::npos);

    const layout::Layout sliding = load_file("sliding_box.json");
    const design::Drawing m = design::plan_drawing(sliding, design::make_report(sliding), {});
    EXPECT_TRUE(has_group(m, "motion"));
    EXPECT_TRUE(has_entry(m, "moving prop's path"));
    int crate = 0;
    for (const design::PlanShape& s : m.shapes) crate += s.group == "motion" && s.name == "crate";
    EXPECT_GE(crate, 3);  // the first key's dot, the path and the arrow at its last key
    EXPECT_FALSE(has_group(design::plan_drawing(lamps, design::make_report(lamps), {}), "motion"));
}

TEST(PlanLegend, ThePngHasTheTitleTheNamesAndTheLegend) {
    const layout::Layout l = load_file("four_rooms.json");
    const design::Drawing d = design::plan_drawing(l, design::make_report(l), {});
    const double k = 50.0;
    const design::PlanSize size = design::plan_size(d, k);
    const image::Pixels image = design::plan_raster(d, k);
    EXPECT_EQ(image.height, size.height);
    const int floor_bottom = static_cast<int>(size.legend_top);
    EXPECT_GT(size.height, floor_bottom + 15);                      // a legend band below the floor
    EXPECT_GT(dark_pixels(image, 0, 28), 100);                      // the title
    EXPECT_GT(dark_pixels(image, floor_bottom, size.height), 200);  // the legend's samples and text
    // The names: the same drawing without its text is lighter where they are.
    design::Drawing bare = d;
    bare.shapes.erase(
        std::remove_if(bare.shapes.begin(), bare.shapes.end(),
                       [](const design::PlanShape& s) { return s.kind == design::PlanShape::Kind::Text; }),
        bare.shapes.end());
    const image::Pixels without = design::plan_raster(bare, k);
    ASSERT_EQ(without.data.size(), image.data.size());
    int changed = 0;
    for (std::size_t i = 0; i < image.data.size(); i += 3) changed += image.data[i] != without.data[i];
    EXPECT_GT(changed, 4 * 60);  // four names of 4 to 7 letters
    // The SVG has every legend line as text, as the PNG draws it.
    const std::string svg = design::plan_svg(d, k);
    for (const design::LegendEntry& e : d.legend)
        EXPECT_NE(svg.find(">" + e.text + "</text>"), std::string::npos) << e.text;
    EXPECT_NE(svg.find("height=\"" + std::to_string(size.height) + ".00\""), std::string::npos);
}

}  // namespace
}  // namespace design_test
