// Where a command's layout comes from: a file, or the built-in default.
#pragma once

#include <optional>
#include <string>

#include "layout/layout.hpp"

namespace impossible::cli {

inline constexpr const char* kDefaultLayoutName = "layouts/default.json";

// Loads and validates the file, or the default layout compiled into the
// program when `path` is empty. Throws InputError with the first problem (and
// how many more there are) on one line.
layout::Layout load_layout_or_default(const std::optional<std::string>& path);

}  // namespace impossible::cli
