// The play area of `generate --play-area-file`: a JSON file holding the
// corners [[x, z], ...], an object {"polygon": [...]}, or a layout (or any
// object) with {"play_area": {"polygon": [...]}}. Unknown fields are
// refused as the layout loader refuses them (FILE:LINE:COLUMN: field:
// unknown field "name", with a "did you mean" hint; names starting with _
// are comments); a layout's own fields are known.
#pragma once

#include <string>
#include <string_view>

#include "base/result.hpp"
#include "math/polygon.hpp"

namespace impossible::design {

// The corners, or the first problem as one line naming `file`.
Result<math::Polygon2> parse_play_area_file(std::string_view text, const std::string& file);

}  // namespace impossible::design
