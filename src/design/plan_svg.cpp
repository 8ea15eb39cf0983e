// The plan as SVG 1.1: one <g> per layer (id = the shape's group), numbers
// with two decimals in pixels, text escaped for XML.
#include <cmath>
#include <cstdio>

#include "design/plan.hpp"

namespace impossible::design {
namespace {

std::string num(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", v);
    std::string s = text;
    return s == "-0.00" ? "0.00" : s;
}

std::string escape(const std::string& text) {
    std::string out;
    for (const char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

std::string colour(const Rgba& c) {
    char text[32];
    std::snprintf(text, sizeof text, "#%02x%02x%02x", static_cast<int>(std::lround(c.r * 255)),
                  static_cast<int>(std::lround(c.g * 255)), static_cast<int>(std::lround(c.b * 255)));
    return text;
}

// A shape at pixel `at(p)`, `k` pixels a unit of its widths and sizes.
template <class At>
std::string shape_svg(const PlanShape& s, At at, double k, double text_pixels, double dash_on, double dash_off) {
    auto px = [&](glm::dvec2 p) {
        const glm::dvec2 q = at(p);
        return num(q.x) + "," + num(q.y);
    };
    const std::string name = s.name.empty() ? "" : " data-name=\"" + escape(s.name) + "\"";
    const std::string opacity = s.colour.a < 1.0 ? " opacity=\"" + num(s.colour.a) + "\"" : "";
    if (s.kind == PlanShape::Kind::Text) {
        const glm::dvec2 p = at(s.points.front());
        return "<text x=\"" + num(p.x) + "\" y=\"" + num(p.y) + "\" font-size=\"" + num(text_pixels) + "\"" +
               (s.centred ? " text-anchor=\"middle\"" : "") + " fill=\"" + colour(s.colour) + "\"" + name + ">" +
               escape(s.text) + "</text>\n";
    }
    std::string points;
    for (const glm::dvec2& p : s.points) points += (points.empty() ? "" : " ") + px(p);
    if (s.kind == PlanShape::Kind::Fill)
        return "<polygon points=\"" + points + "\" fill=\"" + colour(s.colour) + "\"" + opacity + name + "/>\n";
    const std::string dash = s.dashed ? " stroke-dasharray=\"" + num(dash_on) + "," + num(dash_off) + "\"" : "";
    return std::string("<") + (s.closed ? "polygon" : "polyline") + " points=\"" + points +
           "\" fill=\"none\" stroke=\"" + colour(s.colour) + "\" stroke-width=\"" + num(s.width * k) +
           "\" stroke-linejoin=\"round\" stroke-linecap=\"round\"" + dash + opacity + name + "/>\n";
}

// The shapes, one <g> per run of one group.
class Groups {
public:
    explicit Groups(std::string& out) : out_(out) {}
    void enter(const std::string& group) {
        if (group == group_) return;
        close();
        group_ = group;
        out_ += "<g id=\"" + escape(group_) + "\">\n";
    }
    void close() {
        if (!group_.empty()) out_ += "</g>\n";
        group_.clear();
    }

private:
    std::string& out_;
    std::string group_;
};

}  // namespace

std::string plan_svg(const Drawing& d, double k) {
    const PlanSize size = plan_size(d, k);
    const std::string width = num(size.width), height = num(size.height);
    std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + width + "\" height=\"" + height +
           "\" viewBox=\"0 0 " + width + " " + height + "\" font-family=\"sans-serif\">\n";
    out += "<title>" + escape(d.title) + "</title>\n";
    out += "<rect x=\"0\" y=\"0\" width=\"" + width + "\" height=\"" + height + "\" fill=\"#ffffff\"/>\n";
    Groups groups(out);
    const auto floor = [&](glm::dvec2 p) {
        return glm::dvec2((p.x - d.min.x) * k, (p.y - d.min.y) * k + size.floor_top);
    };
    for (const PlanShape& s : d.shapes) {
        groups.enter(s.group);
        out += shape_svg(s, floor, k, label_pixels(s, k), 0.12 * k, 0.08 * k);
    }
    for (const PlanShape& s : plan_overlay(d, k)) {
        groups.enter(s.group);
        out += shape_svg(
            s, [](glm::dvec2 p) { return p; }, 1.0, s.size, 5.0, 3.0);
    }
    groups.close();
    out += "</svg>\n";
    return out;
}

}  // namespace impossible::design
