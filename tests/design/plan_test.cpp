// The plan: well-formed SVG with the expected layers, and a raster of it.
#include "design_test_util.hpp"

#include <map>
#include <stack>

#include "design/plan.hpp"
#include "design/tour.hpp"

namespace design_test {
namespace {

struct Element {
    std::string name;
    std::map<std::string, std::string> attributes;
};

// A small XML well-formedness check: every tag closed in order, attributes
// quoted and not repeated, only the five predefined entities. Returns the
// elements in document order, or fails the test.
std::vector<Element> parse_xml(const std::string& xml) {
    std::vector<Element> out;
    std::stack<std::string> open;
    std::size_t i = 0;
    auto fail = [&](const std::string& why) {
        ADD_FAILURE() << why << " at offset " << i;
        return std::vector<Element>{};
    };
    if (xml.compare(0, 5, "<?xml") == 0) i = xml.find("?>") + 2;
    while (i < xml.size()) {
        if (xml[i] != '<') {
            const std::size_t next = xml.find('<', i);
            const std::string text = xml.substr(i, next - i);
            for (std::size_t a = text.find('&'); a != std::string::npos; a = text.find('&', a + 1)) {
                const std::string entity = text.substr(a, text.find(';', a) - a + 1);
                if (entity != "&amp;" && entity != "&lt;" && entity != "&gt;" && entity != "&quot;" &&
                    entity != "&apos;")
                    return fail("bad entity " + entity);
            }
            if (open.empty() && text.find_first_not_of(" \n") != std::string::npos)
                return fail("text outside the root");
            i = next == std::string::npos ? xml.size() : next;
            continue;
        }
        const std::size_t end = xml.find('>', i);
        if (end == std::string::npos) return fail("unclosed tag");
        std::string tag = xml.substr(i + 1, end - i - 1);
        i = end + 1;
        if (tag[0] == '/') {
            if (open.empty() || open.top() != tag.substr(1)) return fail("mismatched </" + tag.substr(1) + ">");
            open.pop();
            continue;
        }
        const bool empty = tag.back() == '/';
        if (empty) tag.pop_back();
        Element e;
        std::size_t p = tag.find_first_of(" \n");
        e.name = tag.substr(0, p);
        if (open.empty() && !out.empty()) return fail("a second root element");
        while (p != std::string::npos && (p = tag.find_first_not_of(" \n", p)) != std::string::npos) {
            const std::size_t eq = tag.find('=', p);
            if (eq == std::string::npos || eq + 1 >= tag.size() || tag[eq + 1] != '"')
                return fail("unquoted attribute");
            const std::size_t close = tag.find('"', eq + 2);
            if (close == std::string::npos) return fail("unterminated attribute");
            const std::string key = tag.substr(p, eq - p);
            if (!e.attributes.emplace(key, tag.substr(eq + 2, close - eq - 2)).second) return fail("repeated " + key);
            p = close + 1;
        }
        out.push_back(e);
        if (!empty) open.push(e.name);
    }
    if (!open.empty()) return fail("unclosed <" + open.top() + ">");
    return out;
}

int count(const std::vector<Element>& elements, const std::string& name, const std::string& key = "",
          const std::string& value = "") {
    int n = 0;
    for (const Element& e : elements)
        if (e.name == name && (key.empty() || (e.attributes.count(key) && e.attributes.at(key) == value))) ++n;
    return n;
}

TEST(Plan, FourRoomsIsWellFormedSvgWithEveryLayer) {
    const layout::Layout l = load_file("four_rooms.json");
    const design::Report r = design::make_report(l);
    const auto tour = design::plan_tour(l);
    ASSERT_TRUE(tour.has_value());
    const design::Drawing d = design::plan_drawing(l, r, tour->poses);
    const std::string svg = design::plan_svg(d, design::plan_scale(d, 800));
    const std::vector<Element> elements = parse_xml(svg);
    ASSERT_FALSE(elements.empty());
    EXPECT_EQ(elements[0].name, "svg");
    EXPECT_EQ(elements[0].attributes.at("xmlns"), "http://www.w3.org/2000/svg");
    for (const char* group : {"grid", "play-area", "rooms", "overlaps", "props", "doors", "start", "path", "labels"})
        EXPECT_EQ(count(elements, "g", "id", group), 1) << group;
    for (const layout::Room& room : l.rooms) EXPECT_GE(count(elements, "polygon", "data-name", room.id), 2) << room.id;
    for (const layout::Portal& p : l.portals) EXPECT_GE(count(elements, "polyline", "data-name", p.id), 1) << p.id;
    EXPECT_EQ(count(elements, "polygon", "data-name", "hall/library"), 1);  // an overlap
    EXPECT_EQ(count(elements, "polyline", "data-name", "walk"), 1);
    // The title, four room names and the legend's lines.
    EXPECT_EQ(count(elements, "text"), 5 + static_cast<int>(d.legend.size()));
}

TEST(Plan, NamesAreEscaped) {
    layout::Layout l = load_file("default.json");
    l.name = "a <b> & \"c\"";
    const design::Drawing d = design::plan_drawing(l, design::make_report(l), {});
    const std::string svg = design::plan_svg(d, 50.0);
    EXPECT_NE(svg.find("a &lt;b&gt; &amp; &quot;c&quot;"), std::string::npos);
    EXPECT_FALSE(parse_xml(svg).empty());
}

TEST(Plan, RasterShowsThePlayAreaAndTheRooms) {
    const layout::Layout l = load_file("default.json");
    const design::Drawing d = design::plan_drawing(l, design::make_report(l), {});
    const image::Pixels image = design::plan_raster(d, 40.0);
    // 4 x 4 m play area plus 0.5 m rounded out to whole metres on each side: 6 m = 240 px.
    EXPECT_EQ(image.width, 240);
    ASSERT_EQ(image.data.size(), static_cast<std::size_t>(image.width) * image.height * 3);
    // The top-left corner is white; a point inside the rooms is not.
    EXPECT_EQ(image.data[0], 255);
    const std::size_t inside = (static_cast<std::size_t>(28 + 40 * 2.5) * image.width + 40 * 2) * 3;
    EXPECT_LT(image.data[inside] + image.data[inside + 1] + image.data[inside + 2], 3 * 250);
}

}  // namespace
}  // namespace design_test
