// glTF materials: base colour factors and textures, samplers, COLOR_0,
// doubleSided and alphaMode, images in bufferViews, data: URIs and files,
// and the messages for what is refused (unknown alpha modes, missing indices, images that
// do not decode or are too large).
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "assets/gltf_model.hpp"
#include "gltf_writer.hpp"
#include "hostile/png_bytes.hpp"
#include "layout_test_util.hpp"

namespace layout_test {
namespace {

namespace fs = std::filesystem;
using impossible::assets::GltfModel;
using impossible::assets::load_gltf_model;
using nlohmann::json;

// A 2x2 RGBA PNG: red, green / blue, half-transparent white.
std::string png_2x2() {
    std::string rows;
    rows += '\0';
    rows += std::string("\xFF\x00\x00\xFF\x00\xFF\x00\xFF", 8);
    rows += '\0';
    rows += std::string("\x00\x00\xFF\xFF\xFF\xFF\xFF\x80", 8);
    return impossible::hostile::png_file(2, 2, 8, 6, rows);
}

std::vector<unsigned char> bytes_of(const std::string& text) { return {text.begin(), text.end()}; }

enum class ImageIn { BufferView, DataUri, File };

class GltfMaterial : public ::testing::Test {
protected:
    fs::path dir;

    void SetUp() override {
        dir =
            temp_path("gltf_material_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }

    std::string path(const std::string& name) const { return (dir / name).string(); }

    // One triangle with TEXCOORD_0 (0,0), (1,0), (0,1), material 0 with a
    // base colour texture (texture 0 → image 0 through sampler 0).
    GltfWriter textured(ImageIn where, const std::string& image = png_2x2()) {
        GltfWriter w;
        const std::vector<float> uv = {0, 0, 1, 0, 0, 1};
        const int uv_view = w.view(uv.data(), uv.size() * sizeof(float));
        w.doc["accessors"].push_back(
            {{"bufferView", uv_view}, {"componentType", 5126}, {"count", 3}, {"type", "VEC2"}});
        const int uv_accessor = int(w.doc["accessors"].size()) - 1;
        w.node({{"mesh", w.mesh({{"attributes", {{"POSITION", w.vec3(kTriangle)}, {"TEXCOORD_0", uv_accessor}}},
                                 {"material", 0}})}});
        w.doc["materials"] =
            json::array({{{"name", "Tiles"},
                          {"pbrMetallicRoughness",
                           {{"baseColorFactor", {1.0, 0.5, 0.25, 1.0}}, {"baseColorTexture", {{"index", 0}}}}}}});
        w.doc["textures"] = json::array({{{"source", 0}, {"sampler", 0}}});
        w.doc["samplers"] =
            json::array({{{"magFilter", 9728}, {"minFilter", 9729}, {"wrapS", 33071}, {"wrapT", 33648}}});
        if (where == ImageIn::BufferView) {
            const int view = w.view(image.data(), image.size());
            w.doc["images"] = json::array({{{"bufferView", view}, {"mimeType", "image/png"}}});
        } else if (where == ImageIn::DataUri) {
            w.doc["images"] = json::array({{{"uri", "data:image/png;base64," + base64(bytes_of(image))}}});
        } else {
            std::ofstream(path("tiles.png"), std::ios::binary) << image;
            w.doc["images"] = json::array({{{"uri", "tiles.png"}}});
        }
        return w;
    }

    GltfModel load_ok(GltfWriter& w, const std::string& name = "m.gltf") {
        w.write(path(name));
        auto loaded = load_gltf_model(path(name), 1000);
        EXPECT_TRUE(loaded) << (loaded ? "" : loaded.error());
        return loaded ? std::move(*loaded) : GltfModel{};
    }
    std::string load_error(GltfWriter& w, const std::string& name = "m.gltf") {
        w.write(path(name));
        const auto loaded = load_gltf_model(path(name), 1000);
        EXPECT_FALSE(loaded);
        return loaded ? "" : loaded.error();
    }
};

void expect_the_2x2_texture(const GltfModel& model) {
    ASSERT_EQ(model.triangles.size(), 1u);
    ASSERT_EQ(model.materials.size(), 1u);
    ASSERT_EQ(model.textures.size(), 1u);
    const ModelTriangle& t = model.triangles[0];
    EXPECT_EQ(t.material, 0);
    EXPECT_EQ(t.uv[0], glm::dvec2(0, 0));
    EXPECT_EQ(t.uv[1], glm::dvec2(1, 0));
    EXPECT_EQ(t.uv[2], glm::dvec2(0, 1));
    EXPECT_EQ(t.color, glm::dvec3(1.0, 0.5, 0.25));
    const Material& m = model.materials[0];
    EXPECT_EQ(m.base_color, glm::dvec4(1.0, 0.5, 0.25, 1.0));
    EXPECT_EQ(m.texture, 0);
    EXPECT_FALSE(m.double_sided);
    EXPECT_EQ(m.alpha_mode, AlphaMode::Opaque);
    const Texture& texture = model.textures[0];
    EXPECT_EQ(texture.sampler.mag_filter, sampler_code::kNearest);
    EXPECT_EQ(texture.sampler.min_filter, sampler_code::kLinear);
    EXPECT_EQ(texture.sampler.wrap_s, sampler_code::kClampToEdge);
    EXPECT_EQ(texture.sampler.wrap_t, sampler_code::kMirroredRepeat);
    ASSERT_NE(texture.image, nullptr);
    EXPECT_EQ(texture.image->width, 2);
    EXPECT_EQ(texture.image->height, 2);
    const std::vector<std::uint8_t> want = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 128};
    EXPECT_EQ(texture.image->data, want);
    EXPECT_EQ(model.texels, 4u);
}

TEST_F(GltfMaterial, ATextureInABufferViewIsDecodedWithItsSamplerAndUvs) {
    GltfWriter w = textured(ImageIn::BufferView);
    expect_the_2x2_texture(load_ok(w));
}

TEST_F(GltfMaterial, ATextureInAGlbBinaryChunkIsDecoded) {
    GltfWriter w = textured(ImageIn::BufferView);
    w.doc["buffers"] = json::array({{{"byteLength", w.bin.size()}}});
    json roots = json::array({0});
    w.doc["scenes"] = json::array({{{"nodes", roots}}});
    write_glb(path("m.glb"), w.doc.dump(), w.bin);
    auto loaded = load_gltf_model(path("m.glb"), 1000);
    ASSERT_TRUE(loaded) << loaded.error();
    expect_the_2x2_texture(*loaded);
}

TEST_F(GltfMaterial, ATextureInADataUriIsDecoded) {
    GltfWriter w = textured(ImageIn::DataUri);
    expect_the_2x2_texture(load_ok(w));
}

TEST_F(GltfMaterial, ATextureInAFileBesideTheModelIsDecoded) {
    GltfWriter w = textured(ImageIn::File);
    expect_the_2x2_texture(load_ok(w));
}

TEST_F(GltfMaterial, AnImageFileOutsideTheModelsFolderOrMissingIsNamed) {
    GltfWriter w = textured(ImageIn::File);
    w.doc["images"][0]["uri"] = "../outside.png";
    EXPECT_EQ(load_error(w), "has image 0 whose file \"../outside.png\" lies outside the model's folder");
    w.doc["images"][0]["uri"] = "gone.png";
    EXPECT_EQ(load_error(w), "has image 0 whose file \"gone.png\" does not exist");
}

TEST_F(GltfMaterial, SamplerDefaultsAreLinearMipmapLinearAndRepeat) {
    GltfWriter w = textured(ImageIn::BufferView);
    w.doc["textures"][0].erase("sampler");
    const GltfModel model = load_ok(w);
    ASSERT_EQ(model.textures.size(), 1u);
    EXPECT_EQ(model.textures[0].sampler.mag_filter, sampler_code::kLinear);
    EXPECT_EQ(model.textures[0].sampler.min_filter, sampler_code::kLinearMipmapLinear);
    EXPECT_EQ(model.textures[0].sampler.wrap_s, sampler_code::kRepeat);
    EXPECT_EQ(model.textures[0].sampler.wrap_t, sampler_code::kRepeat);
    GltfWriter v = textured(ImageIn::BufferView);
    v.doc["samplers"][0] = json::object();  // a sampler that leaves everything out
    const GltfModel empty = load_ok(v);
    ASSERT_EQ(empty.textures.size(), 1u);
    EXPECT_EQ(empty.textures[0].sampler.mag_filter, sampler_code::kLinear);
    EXPECT_EQ(empty.textures[0].sampler.min_filter, sampler_code::kLinearMipmapLinear);
}

TEST_F(GltfMaterial, NormalizedByteTexCoordsAreRead) {
    GltfWriter w = textured(ImageIn::BufferView);
    const std::vector<unsigned char> uv = {0, 255, 255, 0, 51, 102, 0, 0};
    const int view = w.view(uv.data(), uv.size());
    w.doc["accessors"].push_back(
        {{"bufferView", view}, {"componentType", 5121}, {"normalized", true}, {"count", 3}, {"type", "VEC2"}});
    w.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_1"] = int(w.doc["accessors"].size()) - 1;
    w.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["texCoord"] = 1;
    const GltfModel model = load_ok(w);
    ASSERT_EQ(model.triangles.size(), 1u);
    EXPECT_EQ(model.triangles[0].uv[0], glm::dvec2(0, 1));
    EXPECT_EQ(model.triangles[0].uv[1], glm::dvec2(1, 0));
    EXPECT_EQ(model.triangles[0].uv[2], glm::dvec2(0.2, 0.4));
}

TEST_F(GltfMaterial, VertexColoursAreReadFromFloatsAndNormalizedBytes) {
    GltfWriter w;
    const int colours = w.vec3({1, 0, 0, 0, 0.5f, 0, 0, 0, 2});  // 2 is clamped to 1
    w.node({{"mesh", w.mesh({{"attributes", {{"POSITION", w.vec3(kTriangle)}, {"COLOR_0", colours}}}})}});
    const GltfModel model = load_ok(w);
    ASSERT_EQ(model.triangles.size(), 1u);
    EXPECT_EQ(model.triangles[0].vertex_color[0], glm::dvec4(1, 0, 0, 1));
    EXPECT_EQ(model.triangles[0].vertex_color[1], glm::dvec4(0, 0.5, 0, 1));
    EXPECT_EQ(model.triangles[0].vertex_color[2], glm::dvec4(0, 0, 1, 1));
    EXPECT_EQ(model.triangles[0].material, -1);
    EXPECT_TRUE(model.materials.empty());

    GltfWriter b;
    const std::vector<unsigned char> rgba = {255, 0, 0, 255, 0, 51, 0, 102, 0, 0, 255, 0};
    const int view = b.view(rgba.data(), rgba.size());
    b.doc["accessors"].push_back(
        {{"bufferView", view}, {"componentType", 5121}, {"normalized", true}, {"count", 3}, {"type", "VEC4"}});
    const int accessor = int(b.doc["accessors"].size()) - 1;
    b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", b.vec3(kTriangle)}, {"COLOR_0", accessor}}}})}});
    const GltfModel bytes = load_ok(b, "b.gltf");
    ASSERT_EQ(bytes.triangles.size(), 1u);
    EXPECT_EQ(bytes.triangles[0].vertex_color[0], glm::dvec4(1, 0, 0, 1));
    EXPECT_EQ(bytes.triangles[0].vertex_color[1], glm::dvec4(0, 0.2, 0, 0.4));
    EXPECT_EQ(bytes.triangles[0].vertex_color[2], glm::dvec4(0, 0, 1, 0));
}

TEST_F(GltfMaterial, AColourAccessorOfTheWrongShapeIsNamed) {
    GltfWriter w;
    const int colours = w.vec3({1, 0, 0, 0, 1, 0});  // two colours for three vertices
    w.node({{"mesh", w.mesh({{"attributes", {{"POSITION", w.vec3(kTriangle)}, {"COLOR_0", colours}}}})}});
    EXPECT_EQ(load_error(w), "has mesh 0 primitive 0 whose COLOR_0 accessor 0 has 2 values for 3 vertices");
    w.doc["accessors"][0]["type"] = "SCALAR";
    w.doc["accessors"][0]["count"] = 3;
    EXPECT_EQ(load_error(w), "has mesh 0 primitive 0 whose COLOR_0 accessor 0 must be VEC3 or VEC4");
}

TEST_F(GltfMaterial, DoubleSidedAndMaskAreRead) {
    GltfWriter w = textured(ImageIn::BufferView);
    w.doc["materials"][0]["doubleSided"] = true;
    w.doc["materials"][0]["alphaMode"] = "MASK";
    w.doc["materials"][0]["alphaCutoff"] = 0.25;
    const GltfModel model = load_ok(w);
    ASSERT_EQ(model.materials.size(), 1u);
    EXPECT_TRUE(model.materials[0].double_sided);
    EXPECT_EQ(model.materials[0].alpha_mode, AlphaMode::Mask);
    EXPECT_EQ(model.materials[0].alpha_cutoff, 0.25);
    w.doc["materials"][0].erase("alphaCutoff");
    const GltfModel defaulted = load_ok(w);
    ASSERT_EQ(defaulted.materials.size(), 1u);
    EXPECT_EQ(defaulted.materials[0].alpha_cutoff, 0.5);
}

TEST_F(GltfMaterial, BlendIsReadAsMaskAtOneHalfAndUnknownModesAreRefused) {
    GltfWriter w = textured(ImageIn::BufferView);
    w.doc["materials"][0]["alphaMode"] = "BLEND";
    w.doc["materials"][0]["alphaCutoff"] = 0.9;  // not read for BLEND
    const GltfModel blend = load_ok(w);
    ASSERT_EQ(blend.materials.size(), 1u);
    EXPECT_TRUE(blend.materials[0].blend);
    EXPECT_EQ(blend.materials[0].alpha_mode, impossible::assets::AlphaMode::Mask);
    EXPECT_EQ(blend.materials[0].alpha_cutoff, 0.5);
    w.doc["materials"][0]["alphaMode"] = "SHINY";
    EXPECT_EQ(load_error(w),
              "has material 0 (\"Tiles\") with alphaMode \"SHINY\"; glTF allows \"OPAQUE\", \"MASK\" and \"BLEND\"");
}

TEST_F(GltfMaterial, ABlendMaterialNoPrimitiveUsesIsNoError) {
    GltfWriter w = textured(ImageIn::BufferView);
    w.doc["materials"].push_back({{"name", "Glass"}, {"alphaMode", "BLEND"}});
    const GltfModel model = load_ok(w);
    EXPECT_EQ(model.materials.size(), 1u);
}

TEST_F(GltfMaterial, MissingTextureSamplerAndImageIndicesAreNamed) {
    GltfWriter w = textured(ImageIn::BufferView);
    w.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["index"] = 3;
    EXPECT_EQ(load_error(w),
              "has material 0 (\"Tiles\") whose baseColorTexture names texture 3, which does not "
              "exist (the model has 1 texture)");
    GltfWriter s = textured(ImageIn::BufferView);
    s.doc["textures"][0]["sampler"] = 2;
    EXPECT_EQ(load_error(s),
              "has texture 0 whose sampler names sampler 2, which does not exist (the model has 1 "
              "sampler)");
    GltfWriter i = textured(ImageIn::BufferView);
    i.doc["textures"][0]["source"] = 4;
    EXPECT_EQ(load_error(i),
              "has texture 0 whose source names image 4, which does not exist (the model has 1 "
              "image)");
    GltfWriter n = textured(ImageIn::BufferView);
    n.doc["textures"][0].erase("source");
    EXPECT_EQ(load_error(n).substr(0, 40), "has texture 0 without a source image (im");
    GltfWriter f = textured(ImageIn::BufferView);
    f.doc["samplers"][0]["magFilter"] = 9987;
    EXPECT_EQ(load_error(f), "has sampler 0 whose magFilter 9987 is not a glTF filter (9728 or 9729)");
}

TEST_F(GltfMaterial, ATextureWithoutItsTexCoordSetIsAnError) {
    GltfWriter w = textured(ImageIn::BufferView);
    w.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["texCoord"] = 2;
    EXPECT_EQ(load_error(w),
              "has mesh 0 primitive 0 whose material 0 reads its base colour texture with "
              "TEXCOORD_2, which the primitive does not have");
}

TEST_F(GltfMaterial, NonFiniteFactorsAndCutoffsAreErrors) {
    GltfWriter w = textured(ImageIn::BufferView);
    w.doc["materials"][0]["alphaMode"] = "MASK";
    w.doc["materials"][0]["alphaCutoff"] = -1;
    EXPECT_EQ(load_error(w), "has material 0 (\"Tiles\") whose alphaCutoff is not a finite number of 0 or more");
    // JSON has no infinity: 1e999 is refused as a number that overflows.
    w.write(path("m.gltf"));
    std::string text = read_text(path("m.gltf"));
    text = replace_once(text, "-1", "1e999");
    std::ofstream(path("inf.gltf"), std::ios::binary) << text;
    const auto loaded = load_gltf_model(path("inf.gltf"), 1000);
    ASSERT_FALSE(loaded);
    EXPECT_NE(loaded.error().find("1e999"), std::string::npos) << loaded.error();
    // tinygltf would keep white for a factor of the wrong length.
    GltfWriter f = textured(ImageIn::BufferView);
    f.doc["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {1, 1, 1};
    EXPECT_EQ(load_error(f), "has material 0 whose baseColorFactor is not 4 numbers");
    f.doc["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {1, 1, "1", 1};
    EXPECT_EQ(load_error(f), "has material 0 whose baseColorFactor is not 4 numbers");
}

TEST_F(GltfMaterial, ImagesThatDoNotDecodeAreNamedWithTheReason) {
    GltfWriter w = textured(ImageIn::BufferView, "this is not an image");
    EXPECT_EQ(load_error(w), "has image 0 that is neither PNG nor JPEG data");
    std::string broken = png_2x2();
    broken.resize(broken.size() - 30);  // cut into the image data
    GltfWriter b = textured(ImageIn::DataUri, broken);
    const std::string error = load_error(b);
    EXPECT_EQ(error.substr(0, 36), "has image 0 that could not be decode") << error;
    GltfWriter m = textured(ImageIn::BufferView);
    m.doc["images"][0]["mimeType"] = "image/webp";
    EXPECT_EQ(load_error(m),
              "has image 0 of the unsupported mimeType \"image/webp\" (only image/png and image/jpeg "
              "are supported)");
}

TEST_F(GltfMaterial, AnImageWiderThanTheLimitIsRefused) {
    std::string rows;
    for (int y = 0; y < 1; ++y) rows += '\0' + std::string(9000 * 4, '\x7F');
    GltfWriter w = textured(ImageIn::BufferView, impossible::hostile::png_file(9000, 1, 8, 6, rows));
    EXPECT_EQ(load_error(w), "has image 0 that is 9000 x 1 pixels; the limit is 8192 pixels on a side");
}

TEST_F(GltfMaterial, AnImageBufferViewOutsideItsBufferIsRefusedBeforeParsing) {
    GltfWriter w = textured(ImageIn::BufferView);
    w.doc["bufferViews"].back()["byteLength"] = 100000;
    EXPECT_EQ(load_error(w).substr(0, 35), "has image 0 whose bufferView 2 (100");
}

TEST_F(GltfMaterial, OnlyUsedMaterialsTexturesAndImagesAreKeptAndDecoded) {
    GltfWriter w = textured(ImageIn::BufferView);
    // Material 0 is unused; the primitive uses material 1, whose texture 1
    // shares image 0 with texture 0 through another sampler. Image 1 is
    // garbage that nothing draws: not decoded, no error.
    w.doc["materials"].push_back(w.doc["materials"][0]);
    w.doc["materials"][1]["name"] = "Second";
    w.doc["materials"][1]["pbrMetallicRoughness"]["baseColorTexture"]["index"] = 1;
    w.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["index"] = 2;
    w.doc["textures"].push_back({{"source", 0}});
    w.doc["textures"].push_back({{"source", 1}});
    const std::string garbage = "garbage";
    const int view = w.view(garbage.data(), garbage.size());
    w.doc["images"].push_back({{"bufferView", view}, {"mimeType", "image/png"}});
    w.doc["meshes"][0]["primitives"][0]["material"] = 1;
    // A second primitive with material 0 would decode the garbage: check
    // that alone is what fails.
    const GltfModel model = load_ok(w);
    ASSERT_EQ(model.materials.size(), 1u);
    ASSERT_EQ(model.textures.size(), 1u);
    EXPECT_EQ(model.triangles[0].material, 0);
    EXPECT_EQ(model.materials[0].texture, 0);
    EXPECT_EQ(model.textures[0].sampler.wrap_s, sampler_code::kRepeat);  // texture 1 has no sampler
    w.doc["meshes"][0]["primitives"].push_back(w.doc["meshes"][0]["primitives"][0]);
    w.doc["meshes"][0]["primitives"][1]["material"] = 0;
    EXPECT_EQ(load_error(w), "has image 1 that is neither PNG nor JPEG data");
}

TEST_F(GltfMaterial, TwoTexturesOfOneImageShareIt) {
    GltfWriter w = textured(ImageIn::BufferView);
    w.doc["materials"].push_back(w.doc["materials"][0]);
    w.doc["materials"][1]["pbrMetallicRoughness"]["baseColorTexture"]["index"] = 1;
    w.doc["textures"].push_back({{"source", 0}});
    w.doc["meshes"][0]["primitives"].push_back(w.doc["meshes"][0]["primitives"][0]);
    w.doc["meshes"][0]["primitives"][1]["material"] = 1;
    const GltfModel model = load_ok(w);
    ASSERT_EQ(model.triangles.size(), 2u);
    ASSERT_EQ(model.materials.size(), 2u);
    ASSERT_EQ(model.textures.size(), 2u);
    EXPECT_EQ(model.textures[0].image, model.textures[1].image);
    EXPECT_EQ(model.texels, 4u);
    EXPECT_EQ(model.triangles[1].material, 1);
}

TEST_F(GltfMaterial, APropInALayoutCarriesItsMaterialsAndTextures) {
    GltfWriter w = textured(ImageIn::BufferView);
    w.write(path("m.gltf"));
    const std::string text =
        replace_once(two_rooms(), "\"props\": [", "\"props\": [ { \"gltf\": \"m.gltf\" }, { \"gltf\": \"./m.gltf\" },");
    const LoadResult r = load_layout_text(text, "t.json", dir.string());
    ASSERT_TRUE(r.layout) << all_messages(r.errors);
    const auto& props = r.layout->rooms[0].props;
    ASSERT_GE(props.size(), 2u);
    const auto& a = std::get<GltfProp>(props[0]);
    const auto& b = std::get<GltfProp>(props[1]);
    ASSERT_EQ(a.textures.size(), 1u);
    ASSERT_EQ(a.materials.size(), 1u);
    EXPECT_EQ(a.triangles[0].material, 0);
    EXPECT_EQ(a.textures[0].image, b.textures[0].image);  // one model, one image
    EXPECT_EQ(summary_text(*r.layout, summarize(*r.layout)).find("textures: 1 image, 0 textured room faces\n") ==
                  std::string::npos,
              false);
}

}  // namespace
}  // namespace layout_test
