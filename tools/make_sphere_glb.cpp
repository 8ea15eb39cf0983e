// make_sphere_glb TRIANGLES OUT.glb: writes a bumpy sphere of at most
// TRIANGLES triangles (see sphere_glb.hpp), for measuring the tracer on
// large models (docs/tracer.md, "Many triangles").
// Exit 0 on success, 1 if the file cannot be written, 2 for a usage error.
#include <cstdio>
#include <cstdlib>

#include "sphere_glb.hpp"

int main(int argc, char** argv) {
    char* end = nullptr;
    const long triangles = argc == 3 ? std::strtol(argv[1], &end, 10) : 0;
    if (argc != 3 || end == argv[1] || *end != '\0' || triangles < 16 || triangles > 100'000'000) {
        std::fprintf(stderr, "usage: make_sphere_glb TRIANGLES OUT.glb (16 <= TRIANGLES <= 100000000)\n");
        return 2;
    }
    const std::vector<unsigned char> glb = impossible::tools::make_sphere_glb(triangles);
    std::FILE* file = std::fopen(argv[2], "wb");
    if (file == nullptr) {
        std::fprintf(stderr, "make_sphere_glb: cannot write %s\n", argv[2]);
        return 1;
    }
    const bool written = std::fwrite(glb.data(), 1, glb.size(), file) == glb.size();
    if (std::fclose(file) != 0 || !written) {
        std::fprintf(stderr, "make_sphere_glb: cannot write %s\n", argv[2]);
        std::remove(argv[2]);
        return 1;
    }
    return 0;
}
