// libFuzzer entry point for the glTF model loader (built with
// -DIMPOSSIBLE_FUZZER=ON where the compiler has libFuzzer). Each input is
// written to a file of its own folder, as a .glb when it starts with the
// .glb magic and as a .gltf otherwise, and loaded: any input must give
// triangles or one error sentence, never a crash, hang or leak. Seeds:
// tests/fuzz/gltf_corpus (the models of the issue-13 defects, the 40 kB
// deeply nested one included) and layouts/models.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

#include "layout/gltf_model.hpp"

namespace {

const std::string& folder() {
    static const std::string path = [] {
        char name[] = "/tmp/gltf_fuzzer_XXXXXX";
        if (::mkdtemp(name) == nullptr) std::abort();
        return std::string(name);
    }();
    return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    const std::string path = folder() + (binary ? "/model.glb" : "/model.gltf");
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    }
    const auto loaded = impossible::layout::detail::load_gltf_triangles(path, 100'000);
    if (!loaded && (loaded.error().empty() || loaded.error().find('\n') != std::string::npos)) std::abort();
    if (loaded && loaded->empty()) std::abort();
    return 0;
}
