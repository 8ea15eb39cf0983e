// The files of layouts/gallery/: four room textures and four glTF models, each
// showing one material feature (a base colour texture, COLOR_0, doubleSided,
// alphaMode MASK), all drawn in code so that the project ships them without
// downloading anything. Every function returns the same bytes on every run:
// the pictures use integer arithmetic only, the models round a few sines and
// cosines to float, and the PNGs are encoded by Debian's libstb (if its
// version changes the PNG bytes may change; run make_gallery_assets again).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace impossible::tools::gallery {

// 8-bit pixels, rows from the top of the picture down, 3 (RGB) or 4 (RGBA)
// channels.
struct Picture {
    int width = 0;
    int height = 0;
    int channels = 3;
    std::vector<std::uint8_t> pixels;
};

// Room textures, each tiling seamlessly.
Picture brick_wall();   // 64 × 64 RGB: four courses of running-bond bricks
Picture floor_tiles();  // 64 × 64 RGB: 2 × 2 tiles, cream and slate, grey grout
Picture wood_planks();  // 64 × 64 RGB: four vertical boards with grain and staggered joints
Picture mural();        // 128 × 128 RGB: an upward arrow, a sun at the top right and
                        // the letter F at the left, to see that it is upright and not mirrored

// Model textures.
Picture crate_side();    // 64 × 64 RGB: framed horizontal boards with a stencilled 7
Picture plant_leaves();  // 128 × 128 RGBA: a stem with leaves; alpha 255 on the plant, 0 around it

// The picture as a PNG file (stb_image_write, default compression).
std::vector<unsigned char> png_of(const Picture& picture);

// Models in metres, standing on y = 0, front faces counter-clockwise, with
// normals; see gallery_models.cpp for each.
std::vector<unsigned char> crate_glb();
std::vector<unsigned char> vertex_colours_glb();
std::vector<unsigned char> double_sided_glb();
std::vector<unsigned char> cutout_glb();

struct File {
    std::string name;  // a file name in layouts/gallery/
    std::vector<unsigned char> bytes;
};

// Every file of layouts/gallery/, in a fixed order.
std::vector<File> gallery_files();

}  // namespace impossible::tools::gallery
