// libFuzzer entry point for the glTF model loader (built with
// -DIMPOSSIBLE_FUZZER=ON where the compiler has libFuzzer). Each input is
// written to a file of its own folder, as a .glb when it starts with the
// .glb magic and as a .gltf otherwise, and loaded: any input must give
// triangles or one error sentence (one line, no control characters, valid
// UTF-8: fuzz_check.hpp), never a crash, hang or leak. Seeds:
// tests/fuzz/gltf_corpus (the models of the issue-13 defects, the 40 kB
// deeply nested one included) and layouts/models.
#include <fcntl.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

#include "assets/gltf_model.hpp"
#include "fuzz_check.hpp"

namespace {

// A file for each kind, kept open in a folder of its own and rewritten in
// place (pwrite, then ftruncate to the new length): opening it with O_TRUNC
// each time frees its block, which costs a millisecond and more on ext4
// mounted with `discard`, more than most runs.
struct InputFile {
    std::string path;
    int fd = -1;
};

const InputFile& input_file(bool binary) {
    static const std::string folder = [] {
        char name[] = "/tmp/gltf_fuzzer_XXXXXX";
        if (::mkdtemp(name) == nullptr) std::abort();
        return std::string(name);
    }();
    auto make = [](const std::string& path) {
        InputFile f{path, ::open(path.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0600)};
        if (f.fd < 0) std::abort();
        return f;
    };
    static const InputFile glb = make(folder + "/model.glb");
    static const InputFile gltf = make(folder + "/model.gltf");
    return binary ? glb : gltf;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    const InputFile& file = input_file(binary);
    if (::pwrite(file.fd, data, size, 0) != static_cast<::ssize_t>(size)) std::abort();
    if (::ftruncate(file.fd, static_cast<::off_t>(size)) != 0) std::abort();
    const std::string& path = file.path;
    const auto loaded = impossible::assets::load_gltf_triangles(path, 100'000);
    if (!loaded) impossible::fuzz::require_clean_line(loaded.error());
    if (loaded) impossible::fuzz::require(!loaded->empty(), "a loaded model has triangles");
    return 0;
}
