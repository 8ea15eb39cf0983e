// The play area of `generate --play-area-file`; see play_area_file.hpp.
#include "design/play_area_file.hpp"

#include "layout/checker.hpp"
#include "layout/json_doc.hpp"
#include "layout/limits.hpp"

namespace impossible::design {

Result<math::Polygon2> parse_play_area_file(std::string_view text, const std::string& file) {
    using layout::detail::Path;
    const layout::detail::JsonParse parsed = layout::detail::parse_json(text);
    layout::detail::Checker check(text, file);
    if (!parsed.document) {
        check.error_at_offset(parsed.error->offset, parsed.error->message);
        return Error{check.take_errors().front().str()};
    }
    const nlohmann::json& j = parsed.document->root;
    const nlohmann::json* list = &j;
    if (j.is_object() && j.contains("play_area")) {
        check.check_fields(Path{}, j, {"format", "version", "name", "play_area", "start", "rooms", "portals"}, {});
        list = &j["play_area"];
        if (list->is_object()) check.check_fields(Path{} / "play_area", *list, {"polygon", "min", "max"}, {});
    } else if (j.is_object()) {
        check.check_fields(Path{}, j, {"polygon"}, {});
    }
    if (check.has_errors()) return Error{check.take_errors().front().str()};
    Path at = j.is_object() && j.contains("play_area") ? Path{} / "play_area" : Path{};
    if (list->is_object() && list->contains("polygon")) {
        list = &(*list)["polygon"];
        at = at / "polygon";
    }
    if (!list->is_array()) return Error{file + ": expected a polygon, [[x, z], ...]"};
    // The loader's limits on a play area: its corners' count and coordinates
    // (a generated layout must load).
    math::Polygon2 poly;
    if (check.expect_array(at, *list, layout::limits::kMaxPlayAreaCorners))
        for (std::size_t i = 0; i < list->size(); ++i) {
            const nlohmann::json& p = (*list)[i];
            if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
                return Error{file + ": every corner must be [x, z]"};
            if (const std::optional<glm::dvec2> c = check.read_vec2(at / i, p, layout::detail::NumberKind::Coordinate))
                poly.push_back(*c);
        }
    if (check.has_errors()) return Error{check.take_errors().front().str()};
    if (const auto problem = math::simple_polygon_problem(poly))
        return Error{file + ": the play area must be a simple polygon: " + problem->message};
    return poly;
}

}  // namespace impossible::design
