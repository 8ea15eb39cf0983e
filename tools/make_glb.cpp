// make_glb OUT.glb: writes the project's chair model (see chair_glb.hpp).
// Exit 0 on success, 1 if the file cannot be written, 2 for a usage error.
#include <cstdio>

#include "chair_glb.hpp"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: make_glb OUT.glb\n");
        return 2;
    }
    const std::vector<unsigned char> glb = impossible::tools::make_chair_glb();
    std::FILE* file = std::fopen(argv[1], "wb");
    if (file == nullptr) {
        std::fprintf(stderr, "make_glb: cannot write %s\n", argv[1]);
        return 1;
    }
    const bool written = std::fwrite(glb.data(), 1, glb.size(), file) == glb.size();
    if (std::fclose(file) != 0 || !written) {
        std::fprintf(stderr, "make_glb: cannot write %s\n", argv[1]);
        std::remove(argv[1]);
        return 1;
    }
    return 0;
}
