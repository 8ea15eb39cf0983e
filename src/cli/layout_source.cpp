#include "cli/layout_source.hpp"

#include "base/embedded.hpp"
#include "cli/errors.hpp"

namespace impossible::cli {

layout::Layout load_layout_or_default(const std::optional<std::string>& path) {
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
    return std::move(*loaded.layout);
}

void declare_files_read(CommandOutputs& outputs, const layout::Layout& layout) {
    for (const assets::FileRead& file : layout.files_read) outputs.input(file.what, file.path);
}

layout::Layout load_layout_or_default(const std::optional<std::string>& path, CommandOutputs& outputs) {
    layout::Layout layout = load_layout_or_default(path);
    declare_files_read(outputs, layout);
    return layout;
}

}  // namespace impossible::cli
