// Hostile PNG and JPEG images (issue 26, defects 4 and 6) as room textures
// and glTF textures: pixels that would come from uninitialised memory (a
// palette index past the PLTE chunk, a JPEG without a scan) are refused with
// a message that says so, by validate, render and trace alike; a truncated
// or corrupt image is named as the PNG or JPEG it is; an image beyond the
// side limit says so, also inside a glTF model; an absolute glTF URI lies
// outside the model's folder.
#include "hostile/hostile_util.hpp"
#include "hostile/jpeg_bytes.hpp"
#include "hostile/png_bytes.hpp"

namespace impossible::hostile {
namespace {

// `png` with `chunk` inserted before its (first) IDAT chunk.
std::string images_with_chunk(std::string png, const std::string& chunk) {
    png.insert(png.find("IDAT") - 4, chunk);
    return png;
}

// 4 × 1 pixels of palette indices 0, 1, `third`, 1 and a PLTE of 2 entries.
std::string images_short_palette_png(unsigned char third) {
    const std::string rows = std::string(1, '\0') + std::string{0, 1, char(third), 1};
    return images_with_chunk(png_file(4, 1, 8, 3, rows), png_chunk("PLTE", "\x10\x20\x30\x40\x50\x60"));
}

class HostileImages : public Hostile {
protected:
    // t.json: lay.json whose first room has every face textured by `file`.
    void room_texture(const std::string& file) {
        std::string layout = slurp(dir_ / "lay.json");
        const size_t id = layout.find("\"id\": \"hall\",");
        ASSERT_NE(id, std::string::npos);
        layout.insert(id, "\"textures\": {\"all\": \"" + file + "\"}, ");
        spit(dir_ / "t.json", layout);
    }
    // g.json: lay.json with a prop showing models/m.gltf, a one-triangle
    // model whose material's texture is the image at `image_uri`, and whose
    // buffer is `buffer_uri` (by default its data inline).
    void model_texture(const std::string& image_uri, const std::string& buffer_uri = "") {
        std::string layout = slurp(dir_ / "lay.json");
        const size_t props = layout.find("\"props\": [");
        ASSERT_NE(props, std::string::npos);
        layout.insert(props + 10, "{\"gltf\":\"models/m.gltf\",\"position\":[0,0,0]},");
        spit(dir_ / "g.json", layout);
        fs::create_directories(dir_ / "models");
        // POSITION (0,0,0), (1,0,0), (0,1,0) then TEXCOORD_0 (0,0), (1,0), (0,1).
        const std::string inline_data =
            "data:application/octet-stream;base64,"
            "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAIA/AAAAAAAAAAAAAIA/";
        spit(dir_ / "models/m.gltf",
             R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":60,"uri":")" +
                 (buffer_uri.empty() ? inline_data : buffer_uri) +
                 R"("}],"bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":24}],)"
                 R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},)"
                 R"({"bufferView":1,"componentType":5126,"count":3,"type":"VEC2"}],)"
                 R"("meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1},"material":0}]}],)"
                 R"("materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}}],)"
                 R"("textures":[{"source":0}],"images":[{"uri":")" +
                 image_uri + R"("}],"nodes":[{"mesh":0}]})");
    }
    // validate, render and trace of `layout` are each refused with `words`,
    // and neither writes a picture.
    void expect_every_command_refuses(const std::string& layout, const std::string& words) {
        expect_refused(run("$BIN validate " + layout), 1, words);
        expect_refused(run("$BIN render " + layout + " --size 32x24 --out r.png"), 1, words);
        expect_refused(run("$BIN trace " + layout + " --size 32x24 --out t.png"), 1, words);
        EXPECT_FALSE(fs::exists(dir_ / "r.png"));
        EXPECT_FALSE(fs::exists(dir_ / "t.png"));
    }
};

// Before: stb_image expanded index 255 from the 254 palette entries the PLTE
// chunk had not set, so validate passed and three traces gave three images.
TEST_F(HostileImages, APaletteIndexPastThePlteIsRefusedByEveryCommand) {
    spit(dir_ / "pal.png", images_short_palette_png(255));
    room_texture("pal.png");
    expect_every_command_refuses(
        "t.json",
        "rooms[0].textures.all: the image \"pal.png\" could not be decoded as PNG: pixel (2, 0) has the palette "
        "index 255, past the 2 entries of its PLTE chunk");
}

TEST_F(HostileImages, APaletteIndexPastThePlteOfAGltfTextureIsRefused) {
    model_texture("tex.png");
    spit(dir_ / "models/tex.png", images_short_palette_png(2));
    expect_every_command_refuses("g.json",
                                 "has image 0 that could not be decoded as PNG: pixel (2, 0) has the palette index "
                                 "2, past the 2 entries of its PLTE chunk");
}

// A JPEG whose headers end at EOI, without a scan, left its pixels unwritten.
TEST_F(HostileImages, AJpegWithoutAScanIsRefused) {
    std::string jpeg = jpeg_file(16, 16);
    jpeg = jpeg.substr(0, jpeg.find("\xFF\xDA")) + "\xFF\xD9";
    spit(dir_ / "noscan.jpg", jpeg);
    room_texture("noscan.jpg");
    expect_refused(run("$BIN validate t.json"), 1,
                   "the image \"noscan.jpg\" could not be decoded as JPEG: it has no image data (no SOS marker "
                   "before its EOI marker)");
}

// Before: "could not be decoded (bad png sig)" or "(expected marker)".
TEST_F(HostileImages, ATruncatedJpegSaysItIsATruncatedJpeg) {
    const std::string jpeg = jpeg_file(64, 64);
    for (const std::size_t keep : {jpeg.size() - 2, jpeg.size() - 5, std::size_t{40}}) {
        spit(dir_ / "cut.jpg", jpeg.substr(0, keep));
        room_texture("cut.jpg");
        expect_refused(run("$BIN validate t.json"), 1,
                       "the image \"cut.jpg\" could not be decoded as JPEG: it is truncated (it ends before its EOI "
                       "marker)");
    }
}

// Before: a damaged CRC went unnoticed, and a deflate block of the reserved
// type 3 said "could not be decoded (no SOI)", a JPEG reason.
TEST_F(HostileImages, ACorruptPngSaysWhatIsWrongWithIt) {
    std::string png = png_file(1, 1, 8, 2, std::string("\0\x10\x20\x30", 4));
    png[png.find("IDAT") + 12] ^= 0x40;  // a pixel byte of the stored block
    spit(dir_ / "crc.png", png);
    room_texture("crc.png");
    expect_refused(run("$BIN validate t.json"), 1,
                   "the image \"crc.png\" could not be decoded as PNG: it has a damaged chunk IDAT (its CRC does not "
                   "match its data)");
    const std::string reserved = {0x78, 0x01, 0x07, 0, 0, 0, 1};  // BFINAL 1, BTYPE 3
    std::string ihdr = be32(1) + be32(1) + std::string{8, 2, 0, 0, 0};
    spit(dir_ / "zlib.png", std::string("\x89PNG\r\n\x1a\n", 8) + png_chunk("IHDR", ihdr) +
                                png_chunk("IDAT", reserved) + png_chunk("IEND", ""));
    room_texture("zlib.png");
    expect_refused(run("$BIN validate t.json"), 1,
                   "the image \"zlib.png\" could not be decoded as PNG: its compressed image data is corrupt");
}

// Before: "could not be decoded (unknown image type)" for both.
TEST_F(HostileImages, AnImageBeyondTheSideLimitSaysSoInAGltfModelToo) {
    model_texture("huge.png");
    spit(dir_ / "models/huge.png", png_file(30000, 30000, 8, 2, std::string(1, '\0')));
    expect_refused(run("$BIN validate g.json"), 1,
                   "has image 0 that is 30000 x 30000 pixels; the limit is 8192 pixels on a side");
    spit(dir_ / "huge.jpg", jpeg_file(65535, 65535).substr(0, 200));
    room_texture("huge.jpg");
    expect_refused(run("$BIN validate t.json"), 1,
                   "the image \"huge.jpg\" is 65535 x 65535 pixels; the limit is 8192 pixels on a side");
}

// Before: tinygltf joined "/x" to the model's folder, and the file "did not
// exist" there.
TEST_F(HostileImages, AnAbsoluteGltfUriLiesOutsideTheModelsFolder) {
    spit(dir_ / "abs.png", png_file(1, 1, 8, 2, std::string("\0\x10\x20\x30", 4)));
    const std::string image = (dir_ / "abs.png").string();
    model_texture(image);
    expect_refused(run("$BIN validate g.json"), 1,
                   "has image 0 whose file \"" + image + "\" lies outside the model's folder");
    model_texture("file://" + image);
    expect_refused(run("$BIN validate g.json"), 1,
                   "has image 0 whose file \"file://" + image + "\" lies outside the model's folder");
    spit(dir_ / "b.bin", std::string(60, '\0'));
    const std::string buffer = (dir_ / "b.bin").string();
    model_texture("abs.png", buffer);
    expect_refused(run("$BIN validate g.json"), 1,
                   "has buffer 0 whose file \"" + buffer + "\" lies outside the model's folder");
}

}  // namespace
}  // namespace impossible::hostile
