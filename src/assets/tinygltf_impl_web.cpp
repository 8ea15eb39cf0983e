// The web build's tinygltf and stb_image_write (the native build links
// Debian's libtinygltf and libstb): their implementations. tinygltf decodes
// no images itself (gltf_sandbox.cpp gives it the loader) and reads files
// only through the callbacks gltf_sandbox.cpp sets; image/png.cpp writes
// PNG files with stb_image_write.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <tiny_gltf.h>

namespace tinygltf {
// The default image loader the TinyGLTF constructor names; gltf_sandbox.cpp
// always replaces it, so it is never called.
bool LoadImageData(Image*, const int, std::string* err, std::string*, int, int, const unsigned char*, int, void*) {
    if (err) *err += "no image loader\n";
    return false;
}
}  // namespace tinygltf
