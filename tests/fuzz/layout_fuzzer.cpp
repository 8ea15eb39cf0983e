// libFuzzer entry point for the layout loader (built with
// -DIMPOSSIBLE_FUZZER=ON and clang). Any input must give either a layout or
// errors, each one line without control characters and valid UTF-8
// (fuzz_check.hpp), never a crash, hang or leak. Texture and glTF paths
// resolve against the current directory: scripts/fuzz.sh runs it where
// gallery/ and models/ are copies of layouts/'s. Seeds: fuzz/layout_corpus.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz_check.hpp"
#include "layout/layout.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const impossible::layout::LoadResult result = impossible::layout::load_layout_text(text, "fuzz.json", ".");
    impossible::fuzz::require(result.layout.has_value() == result.errors.empty(),
                              "a layout, or errors, never both or neither");
    for (const impossible::layout::Diagnostic& d : result.errors) {
        impossible::fuzz::require(!d.message.empty(), "a diagnostic with a message");
        impossible::fuzz::require_clean_line(d.str());
    }
    return 0;
}
