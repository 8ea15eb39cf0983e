#include "cli/layout_source.hpp"

#include <ostream>

#include "base/embedded.hpp"
#include "cli/errors.hpp"

namespace impossible::cli {

namespace {

layout::Layout load(const std::optional<std::string>& path, std::ostream* warnings) {
    layout::LoadResult loaded =
        path ? layout::load_layout_file(*path)
             : layout::load_layout_text(std::string(embedded::find(kDefaultLayoutName)),
                                        "<built-in " + std::string(kDefaultLayoutName) + ">", ".");
    if (!loaded.errors.empty()) {
        std::string message = loaded.errors.front().str();
        if (loaded.errors.size() > 1)
            message += " (and " + std::to_string(loaded.errors.size() - 1) +
                       " more problems; 'impossible validate' lists them all)";
        throw InputError(message);
    }
    if (warnings)
        for (const layout::Diagnostic& d : loaded.loud_warnings) *warnings << "warning: " << d.str() << "\n";
    return std::move(*loaded.layout);
}

}  // namespace

layout::Layout load_layout_or_default(const std::optional<std::string>& path) { return load(path, nullptr); }

void declare_files_read(CommandOutputs& outputs, const layout::Layout& layout) {
    for (const assets::FileRead& file : layout.files_read) outputs.input(file.what, file.path);
}

layout::Layout load_layout_or_default(const std::optional<std::string>& path, CommandOutputs& outputs) {
    layout::Layout layout = load(path, nullptr);
    declare_files_read(outputs, layout);
    return layout;
}

layout::Layout load_layout_or_default(const std::optional<std::string>& path, CommandOutputs& outputs,
                                      std::ostream& warnings) {
    layout::Layout layout = load(path, &warnings);
    declare_files_read(outputs, layout);
    return layout;
}

}  // namespace impossible::cli
