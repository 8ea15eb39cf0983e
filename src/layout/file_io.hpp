// The loader reads files through base/file_io.hpp (size limits, no hanging
// on pipes); these names keep the loader's code short.
#pragma once

#include "base/file_io.hpp"

namespace impossible::layout::detail {

using impossible::check_readable_file;
using impossible::read_file_bytes;

}  // namespace impossible::layout::detail
