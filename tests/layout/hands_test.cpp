// Top-level `hands` (layout-format.md, "Moving props, hands and crossing
// objects"): a box with a colour or a glTF model with a scale, exactly one.
#include <fstream>

#include "layout_test_util.hpp"

namespace layout_test {
namespace {

std::string with_hands(const std::string& hands) {
    return replace_once(two_rooms(), "\"version\": 1,", "\"version\": 1,\n  \"hands\": " + hands + ",");
}

TEST(LayoutHands, WithoutHandsTheDefaultBox) {
    const Layout l = expect_valid(two_rooms());
    EXPECT_FALSE(l.hands.model.has_value());
    EXPECT_EQ(l.hands.box, glm::dvec3(0.08, 0.04, 0.16));
    EXPECT_EQ(l.hands.color, glm::dvec3(0.85, 0.70, 0.60));
}

TEST(LayoutHands, ABoxWithItsColour) {
    Layout l = expect_valid(with_hands(R"({"box": [0.1, 0.05, 0.2], "color": [0.2, 0.4, 0.6]})"));
    EXPECT_FALSE(l.hands.model.has_value());
    EXPECT_EQ(l.hands.box, glm::dvec3(0.1, 0.05, 0.2));
    EXPECT_EQ(l.hands.color, glm::dvec3(0.2, 0.4, 0.6));
    l = expect_valid(with_hands(R"({"box": [0.1, 0.05, 0.2]})"));
    EXPECT_EQ(l.hands.color, glm::dvec3(0.85, 0.70, 0.60));  // the default colour
}

TEST(LayoutHands, AGltfModelWithItsScale) {
    Layout l = expect_valid(with_hands("{\"gltf\": \"" + kChairGlb + "\", \"scale\": 0.25}"));
    ASSERT_TRUE(l.hands.model.has_value());
    const GltfProp& m = *l.hands.model;
    EXPECT_EQ(m.path, kChairGlb);
    EXPECT_EQ(m.scale, 0.25);
    EXPECT_EQ(m.position, glm::dvec3(0.0));
    EXPECT_EQ(m.yaw_deg, 0.0);
    EXPECT_FALSE(m.triangles.empty());
    EXPECT_FALSE(m.materials.empty());
    ASSERT_FALSE(l.files_read.empty());
    EXPECT_EQ(l.files_read.back().path, m.resolved_path);
    l = expect_valid(with_hands("{\"gltf\": \"" + kChairGlb + "\"}"));
    ASSERT_TRUE(l.hands.model.has_value());
    EXPECT_EQ(l.hands.model->scale, 1.0);  // the default scale
}

TEST(LayoutHands, AGltfHandListsItsBufferAndImageFiles) {
    impossible::test::TempDir dir("hands_gltf");
    const float data[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1};  // POSITION, then TEXCOORD_0
    std::ofstream(dir / "h.bin", std::ios::binary).write(reinterpret_cast<const char*>(data), sizeof data);
    std::ofstream(dir / "h.png", std::ios::binary)
        << read_text(std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/gallery/brick.png");
    std::ofstream(dir / "h.gltf")
        << R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":60,"uri":"h.bin"}],)"
           R"("bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":24}],)"
           R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},)"
           R"({"bufferView":1,"componentType":5126,"count":3,"type":"VEC2"}],)"
           R"("meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1},"material":0}]}],)"
           R"("materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}}],)"
           R"("textures":[{"source":0}],"images":[{"uri":"h.png"}],"nodes":[{"mesh":0}]})";
    const LoadResult loaded = load_layout_text(with_hands(R"({"gltf": "h.gltf"})"), "t.json", dir.path().string());
    ASSERT_TRUE(loaded.layout) << all_messages(loaded.errors);
    const std::string model = (dir / "h.gltf").string();
    const std::string canonical = std::filesystem::canonical(dir.path()).string();
    std::string listed;
    for (const FileRead& f : loaded.layout->files_read) listed += f.what + " " + f.path + "\n";
    EXPECT_EQ(listed, "the glTF model " + model + "\na file of the glTF model " + model + ": " + canonical +
                          "/h.bin\na file of the glTF model " + model + ": " + canonical + "/h.png\n");
    ASSERT_TRUE(loaded.layout->hands.model.has_value());
    EXPECT_EQ(loaded.layout->hands.model->triangles.size(), 1u);
    EXPECT_EQ(loaded.layout->hands.model->textures.size(), 1u);
}

TEST(LayoutHands, ExactlyOneOfBoxAndGltf) {
    const std::string both = with_hands("{\"box\": [0.1, 0.1, 0.1], \"gltf\": \"" + kChairGlb + "\"}");
    expect_one_error(both, "{\"box\"", "hands: hands are either a \"box\" or a \"gltf\" model, not both");
    expect_one_error(with_hands(R"({"color": [1, 0, 0]})"), "{\"color\"", "hands: missing field \"box\" or \"gltf\"");
    expect_one_error(with_hands("{}"), "{},", "hands: missing field \"box\" or \"gltf\"");
}

TEST(LayoutHands, ScaleOnlyWithGltfAndColourOnlyWithBox) {
    expect_one_error(with_hands(R"({"box": [0.1, 0.1, 0.1], "scale": 2})"), "\"scale\"",
                     "hands.scale: a box hand has no scale (only a \"gltf\" hand is scaled)");
    expect_one_error(with_hands("{\"gltf\": \"" + kChairGlb + "\", \"color\": [1, 0, 0]}"), "\"color\": [1, 0, 0]",
                     "hands.color: a glTF hand has no color");
}

TEST(LayoutHands, TheBoxIsThreeLengths) {
    expect_one_error(with_hands(R"({"box": [0.1, 0.1]})"), "[0.1, 0.1]",
                     "hands.box: must be an array of 3 numbers [W, H, D] (got an array of 2)");
    expect_one_error(with_hands(R"({"box": 0.1})"), "0.1}",
                     "hands.box: must be an array of 3 numbers [W, H, D] (got a number)");
    expect_one_error(with_hands(R"({"box": [0.1, 0, 0.1]})"), "0, 0.1]",
                     "hands.box[1]: must be greater than 0 (got 0)");
    expect_one_error(with_hands(R"({"box": [0.1, 0.1, 1e6]})"), "1e6", "hands.box[2]: 1000000 is too large");
    expect_one_error(with_hands(R"({"box": [0.1, 0.1, 0.1], "color": [2, 0, 0]})"), "2, 0, 0",
                     "hands.color[0]: colour component 2 is outside 0..1");
}

TEST(LayoutHands, TheModelMustLoadAndItsScaleBePositive) {
    expect_one_error(with_hands(R"({"gltf": "models/no_such_hand.glb"})"), "\"models/no_such_hand.glb\"",
                     "hands.gltf: the model ");
    expect_one_error(with_hands(R"({"gltf": ""})"), "\"\"}", "hands.gltf: must name a .glb or .gltf file");
    expect_one_error(with_hands(R"({"gltf": 3})"), "3}", "hands.gltf: must be a string (got a number)");
    expect_one_error(with_hands("{\"gltf\": \"" + kChairGlb + "\", \"scale\": 0}"), "0}",
                     "hands.scale: must be greater than 0 (got 0)");
    expect_one_error(with_hands("{\"gltf\": \"" + kChairGlb + "\", \"scale\": -1}"), "-1}",
                     "hands.scale: must be greater than 0 (got -1)");
}

TEST(LayoutHands, HandsIsAnObjectWithKnownFields) {
    expect_one_error(with_hands("[0.1, 0.1, 0.1]"), "[0.1, 0.1, 0.1]", "hands: must be an object (got an array)");
    expect_one_error(with_hands(R"({"box": [0.1, 0.1, 0.1], "colour": [1, 0, 0]})"), "\"colour\"",
                     "hands.colour: unknown field \"colour\" (did you mean \"color\"?)");
    expect_valid(with_hands(R"({"_note": "small hands", "box": [0.05, 0.02, 0.1]})"));
}

}  // namespace
}  // namespace layout_test
