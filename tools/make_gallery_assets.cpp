// make_gallery_assets OUTDIR: writes the files of layouts/gallery/ (room
// textures and models, see gallery_assets.hpp) into OUTDIR, which must exist.
// Exit 0 on success, 1 if a file cannot be made or written, 2 for a usage error.
#include <cstdio>
#include <string>

#include "gallery_assets.hpp"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: make_gallery_assets OUTDIR\n");
        return 2;
    }
    for (const impossible::tools::gallery::File& f : impossible::tools::gallery::gallery_files()) {
        const std::string path = std::string(argv[1]) + "/" + f.name;
        if (f.bytes.empty()) {
            std::fprintf(stderr, "make_gallery_assets: cannot encode %s\n", f.name.c_str());
            return 1;
        }
        std::FILE* file = std::fopen(path.c_str(), "wb");
        if (file == nullptr) {
            std::fprintf(stderr, "make_gallery_assets: cannot write %s\n", path.c_str());
            return 1;
        }
        const bool written = std::fwrite(f.bytes.data(), 1, f.bytes.size(), file) == f.bytes.size();
        if (std::fclose(file) != 0 || !written) {
            std::fprintf(stderr, "make_gallery_assets: cannot write %s\n", path.c_str());
            std::remove(path.c_str());
            return 1;
        }
    }
    return 0;
}
