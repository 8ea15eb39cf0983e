// Layout::files_read: every file the loader opened besides the layout, as
// commands check their outputs against (cli/layout_source.hpp): each room
// texture and glTF model once, in the order read, with what it is.
#include <fstream>

#include "layout_test_util.hpp"

namespace layout_test {
namespace {

std::string listed(const Layout& layout) {
    std::string out;
    for (const FileRead& f : layout.files_read) out += f.what + " " + f.path + "\n";
    return out;
}

TEST(FilesRead, TheGalleryListsEachTextureAndModelOnce) {
    const LoadResult loaded = load_layout_file(std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/gallery.json");
    ASSERT_TRUE(loaded.layout) << all_messages(loaded.errors);
    const std::string dir = std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/gallery/";
    const std::string list = listed(*loaded.layout);
    for (const char* texture : {"brick.png", "tiles.png", "wood.png", "mural.png"})
        EXPECT_NE(list.find("the texture " + dir + texture + "\n"), std::string::npos) << texture << "\n" << list;
    for (const char* model : {"crate.glb", "cutout.glb", "double_sided.glb", "vertex_colours.glb"})
        EXPECT_NE(list.find("the glTF model " + dir + model + "\n"), std::string::npos) << model << "\n" << list;
    EXPECT_EQ(loaded.layout->files_read.size(), 8u) << list;  // the .glb files hold their buffers and images
}

TEST(FilesRead, AGltfListsItsBufferAndImageFiles) {
    impossible::test::TempDir dir("files_read_gltf");
    const float data[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1};  // POSITION, then TEXCOORD_0
    std::ofstream(dir / "m.bin", std::ios::binary).write(reinterpret_cast<const char*>(data), sizeof data);
    std::ofstream(dir / "t.png", std::ios::binary)
        << read_text(std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/gallery/brick.png");
    std::ofstream(dir / "m.gltf")
        << R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":60,"uri":"m.bin"}],)"
           R"("bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":24}],)"
           R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},)"
           R"({"bufferView":1,"componentType":5126,"count":3,"type":"VEC2"}],)"
           R"("meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1},"material":0}]}],)"
           R"("materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}}],)"
           R"("textures":[{"source":0}],"images":[{"uri":"t.png"}],"nodes":[{"mesh":0}]})";
    const std::string text =
        replace_once(two_rooms(), "\"props\": [", R"("props": [{"gltf": "m.gltf", "position": [0, 0, 0]},)");
    const LoadResult loaded = load_layout_text(text, "t.json", dir.path().string());
    ASSERT_TRUE(loaded.layout) << all_messages(loaded.errors);
    const std::string model = (dir / "m.gltf").string();
    const std::string canonical = std::filesystem::canonical(dir.path()).string();
    EXPECT_EQ(listed(*loaded.layout), "the glTF model " + model + "\na file of the glTF model " + model + ": " +
                                          canonical + "/m.bin\na file of the glTF model " + model + ": " + canonical +
                                          "/t.png\n");
}

}  // namespace
}  // namespace layout_test
