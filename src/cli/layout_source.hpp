// Where a command's layout comes from: a file, or the built-in default.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>

#include "cli/output_files.hpp"
#include "layout/layout.hpp"

namespace impossible::cli {

inline constexpr const char* kDefaultLayoutName = "layouts/default.json";

// Loads and validates the file, or the default layout compiled into the
// program when `path` is empty. Throws InputError with the first problem (and
// how many more there are) on one line.
layout::Layout load_layout_or_default(const std::optional<std::string>& path);

// The same for a command that writes files (the layout itself declared as
// an input of `outputs` before): then declares every file the loader read
// (textures, glTF models and their buffers and images) as an input, which
// throws UsageError, before any work, when an output names one of them.
layout::Layout load_layout_or_default(const std::optional<std::string>& path, CommandOutputs& outputs);

// The same, printing the loader's loud warnings (layout::LoadResult, e.g. a
// door whose normal points out of its room) to `warnings` as
// "warning: FILE:LINE:COLUMN: field: message" lines.
layout::Layout load_layout_or_default(const std::optional<std::string>& path, CommandOutputs& outputs,
                                      std::ostream& warnings);

// Declares the files `layout` was read from, but the layout file itself, as
// inputs of `outputs`.
void declare_files_read(CommandOutputs& outputs, const layout::Layout& layout);

}  // namespace impossible::cli
