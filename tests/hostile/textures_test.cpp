// Hostile room textures and glTF images through the program: a texture that
// is a FIFO or a device, and a glTF image file that is a FIFO, end at once in
// one line naming the file, with exit status 1; a BLEND material is named
// in a warning.
#include "hostile/hostile_util.hpp"
#include "hostile/png_bytes.hpp"

namespace impossible::hostile {
namespace {

class HostileTextures : public Hostile {
protected:
    // t.json: lay.json whose first room has `textures`.
    void layout_with_textures(const std::string& textures) {
        std::string layout = slurp(dir_ / "lay.json");
        const size_t id = layout.find("\"id\": \"hall\",");
        ASSERT_NE(id, std::string::npos);
        layout.insert(id, "\"textures\": " + textures + ", ");
        spit(dir_ / "t.json", layout);
    }
    // g.json: lay.json with a prop showing models/m.gltf.
    void layout_with_model() {
        std::string layout = slurp(dir_ / "lay.json");
        const size_t props = layout.find("\"props\": [");
        ASSERT_NE(props, std::string::npos);
        layout.insert(props + 10, "{\"gltf\":\"models/m.gltf\",\"position\":[0,0,0]},");
        spit(dir_ / "g.json", layout);
    }
    // A one-triangle model whose material has a texture of image `image`.
    void textured_model(const std::string& image, const std::string& alpha_mode = "OPAQUE") {
        fs::create_directories(dir_ / "models");
        // POSITION (0,0,0), (1,0,0), (0,1,0) then TEXCOORD_0 (0,0), (1,0), (0,1).
        spit(dir_ / "models/m.gltf",
             R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":60,"uri":"data:application/octet-stream;base64,)"
             R"(AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAIA/AAAAAAAAAAAAAIA/"}],)"
             R"("bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":24}],)"
             R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},)"
             R"({"bufferView":1,"componentType":5126,"count":3,"type":"VEC2"}],)"
             R"("meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1},"material":0}]}],)"
             R"("materials":[{"name":"Glass","alphaMode":")" +
                 alpha_mode +
                 R"(","pbrMetallicRoughness":{"baseColorTexture":{"index":0}}}],)"
                 R"("textures":[{"source":0}],"images":[{"uri":")" +
                 image + R"("}],"nodes":[{"mesh":0}]})");
    }
};

TEST_F(HostileTextures, ARoomTextureThatIsAFifoOrADeviceIsRefusedAtOnce) {
    layout_with_textures(R"({"floor": "pipe.png"})");
    const Outcome fifo = run("mkfifo pipe.png; $BIN validate t.json");
    expect_refused(fifo, 1, "rooms[0].textures.floor: the image \"pipe.png\" is not a regular file");
    EXPECT_LT(fifo.seconds, 5.0);
    layout_with_textures(R"({"all": "/dev/zero"})");
    const Outcome zero = run("$BIN validate t.json");
    expect_refused(zero, 1, "rooms[0].textures.all: the image \"/dev/zero\" is not a regular file");
    EXPECT_LT(zero.seconds, 5.0);
}

TEST_F(HostileTextures, AValidRoomTextureIsCountedByValidate) {
    std::string rows;
    rows += '\0';
    rows += std::string("\x10\x20\x30\xFF", 4);
    spit(dir_ / "one.png", png_file(1, 1, 8, 6, rows));
    layout_with_textures(R"({"all": "one.png"})");
    const Outcome r = run("$BIN validate t.json");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("textures: 1 image, 6 textured room faces\n"), std::string::npos) << r.out;
}

TEST_F(HostileTextures, AGltfImageFileThatIsAFifoIsNamedAsOne) {
    textured_model("tex.png");
    layout_with_model();
    const Outcome r = run("mkfifo models/tex.png; $BIN validate g.json");
    expect_refused(r, 1, "has image 0 whose file \"tex.png\" is not a regular file");
    EXPECT_LT(r.seconds, 5.0);
}

TEST_F(HostileTextures, ABlendMaterialIsNamedInAWarning) {
    textured_model("tex.png", "BLEND");
    spit(dir_ / "models/tex.png", png_file(1, 1, 8, 6, std::string("\0\x10\x20\x30\xFF", 5)));
    layout_with_model();
    const Outcome r = run("$BIN validate g.json");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("warning: g.json:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("has material 0 (\"Glass\") with alphaMode \"BLEND\", drawn alpha-tested at 0.5"),
              std::string::npos)
        << r.err;
}

// stb_image names an unknown critical chunk by its four type bytes; a type
// of a newline and an escape sequence must not reach the terminal (found by
// gltf_fuzzer): the message stays one printable line. The chunk check now
// refuses such a type first, by its offset.
TEST_F(HostileTextures, AnUnknownChunkTypeWithControlBytesIsQuotedPrintably) {
    std::string png = png_file(1, 1, 8, 2, std::string("\0\x10\x20\x30", 4));
    const std::size_t iend = png.size() - 12;
    png.insert(iend, png_chunk(std::string("\n\x1b[H", 4), "x"));
    spit(dir_ / "bad.png", png);
    layout_with_textures(R"({"floor": "bad.png"})");
    const Outcome r = run("$BIN validate t.json");
    expect_refused(r, 1,
                   "rooms[0].textures.floor: the image \"bad.png\" could not be decoded as PNG: it has a damaged "
                   "chunk at byte 60 (its type is not four letters)");
    EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << r.err;
}

}  // namespace
}  // namespace impossible::hostile
