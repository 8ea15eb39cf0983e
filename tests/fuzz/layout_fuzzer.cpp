// libFuzzer entry point for the layout loader (built with
// -DIMPOSSIBLE_FUZZER=ON and clang). Any input must give either a layout or
// errors, never a crash, hang or leak; glTF paths resolve against the
// current directory.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "layout/layout.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const impossible::layout::LoadResult result =
        impossible::layout::load_layout_text(text, "fuzz.json", ".");
    if (result.layout.has_value() != result.errors.empty()) std::abort();
    for (const impossible::layout::Diagnostic& d : result.errors) {
        if (d.message.empty() || d.str().empty()) std::abort();
    }
    return 0;
}
