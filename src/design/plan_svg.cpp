// The plan as SVG 1.1: one <g> per layer (id = the shape's group), numbers
// with two decimals in pixels, text escaped for XML.
#include <cmath>
#include <cstdio>

#include "design/plan.hpp"

namespace impossible::design {
namespace {

constexpr double kTitleHeight = 28.0;  // px above the floor for the title

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

std::string shape_svg(const Drawing& d, const PlanShape& s, double k) {
    auto px = [&](glm::dvec2 p) { return num((p.x - d.min.x) * k) + "," + num((p.y - d.min.y) * k + kTitleHeight); };
    const std::string name = s.name.empty() ? "" : " data-name=\"" + escape(s.name) + "\"";
    const std::string opacity = s.colour.a < 1.0 ? " opacity=\"" + num(s.colour.a) + "\"" : "";
    if (s.kind == PlanShape::Kind::Text) {
        const glm::dvec2 p = s.points.front();
        return "<text x=\"" + num((p.x - d.min.x) * k) + "\" y=\"" + num((p.y - d.min.y) * k + kTitleHeight) +
               "\" font-size=\"" + num(s.size * k) + "\" text-anchor=\"middle\" fill=\"" + colour(s.colour) + "\"" +
               name + ">" + escape(s.text) + "</text>\n";
    }
    std::string points;
    for (const glm::dvec2& p : s.points) points += (points.empty() ? "" : " ") + px(p);
    if (s.kind == PlanShape::Kind::Fill)
        return "<polygon points=\"" + points + "\" fill=\"" + colour(s.colour) + "\"" + opacity + name + "/>\n";
    const std::string dash = s.dashed ? " stroke-dasharray=\"" + num(0.12 * k) + "," + num(0.08 * k) + "\"" : "";
    return std::string("<") + (s.closed ? "polygon" : "polyline") + " points=\"" + points +
           "\" fill=\"none\" stroke=\"" + colour(s.colour) + "\" stroke-width=\"" + num(s.width * k) +
           "\" stroke-linejoin=\"round\" stroke-linecap=\"round\"" + dash + opacity + name + "/>\n";
}

}  // namespace

std::string plan_svg(const Drawing& d, double k) {
    const double width = std::ceil((d.max.x - d.min.x) * k), height = std::ceil((d.max.y - d.min.y) * k + kTitleHeight);
    std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + num(width) + "\" height=\"" +
           num(height) + "\" viewBox=\"0 0 " + num(width) + " " + num(height) + "\" font-family=\"sans-serif\">\n";
    out += "<title>" + escape(d.title) + "</title>\n";
    out += "<rect x=\"0\" y=\"0\" width=\"" + num(width) + "\" height=\"" + num(height) + "\" fill=\"#ffffff\"/>\n";
    out += "<text x=\"8\" y=\"19\" font-size=\"14\" fill=\"#333333\">" + escape(d.title) + "</text>\n";
    std::string group;
    for (const PlanShape& s : d.shapes) {
        if (s.group != group) {
            if (!group.empty()) out += "</g>\n";
            group = s.group;
            out += "<g id=\"" + escape(group) + "\">\n";
        }
        out += shape_svg(d, s, k);
    }
    if (!group.empty()) out += "</g>\n";
    out += "</svg>\n";
    return out;
}

}  // namespace impossible::design
