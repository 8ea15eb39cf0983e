// Hostile and unusual glTF models (issue 13, parts 3 and 4): JSON nested deep
// enough to crash tinygltf, buffers whose byteLength is wrong or whose file is
// not a regular file, references to missing bufferViews and materials,
// required extensions, absurd transforms and coordinates; and what is read:
// sparse accessors, triangle strips and fans, skins and morph targets.
#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "assets/gltf_model.hpp"
#include "gltf_writer.hpp"
#include "layout_test_util.hpp"

namespace layout_test {
namespace {

namespace fs = std::filesystem;

class GltfHardening : public impossible::test::TempDirTest {
protected:
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    std::string load_error(const std::string& file) {
        const auto loaded = impossible::assets::load_gltf_triangles(file, 1000000);
        EXPECT_FALSE(loaded);
        return loaded ? "" : loaded.error();
    }
    std::vector<ModelTriangle> load_ok(const std::string& file) {
        auto loaded = impossible::assets::load_gltf_triangles(file, 1000000);
        EXPECT_TRUE(loaded) << (loaded ? "" : loaded.error());
        return loaded ? *loaded : std::vector<ModelTriangle>{};
    }
    // One triangle in one node; `edit` changes the document before it is written.
    template <class Edit>
    std::string model(const std::string& name, Edit edit) {
        GltfWriter w;
        w.node({{"mesh", w.mesh({{"attributes", {{"POSITION", w.vec3(kTriangle)}}}})}});
        w.write(path(name));
        edit(w.doc);
        std::ofstream(path(name), std::ios::binary) << w.doc.dump();
        return path(name);
    }
};

std::string nested(std::size_t depth) { return std::string(depth, '[') + std::string(depth, ']'); }

TEST_F(GltfHardening, JsonNestedTwentyThousandDeepIsRefusedBeforeTinygltf) {
    // 40 kB: tinygltf copies `extras` recursively and overflows the stack.
    std::string text = R"({"asset":{"version":"2.0"},"extras":)" + nested(20'000) + "}";
    std::ofstream(path("deep.gltf"), std::ios::binary) << text;
    EXPECT_EQ(load_error(path("deep.gltf")),
              "nests its JSON more than 64 levels deep (at byte offset 99); a glTF file needs about 8");
    write_glb(path("deep.glb"), text, {});
    EXPECT_EQ(load_error(path("deep.glb")).rfind("nests its JSON more than 64 levels deep (at byte offset ", 0), 0u);
    // Brackets inside strings do not count; 64 levels are allowed.
    std::string fine = model("strings.gltf", [](json& doc) { doc["extras"] = {{"s", std::string(500, '[')}}; });
    EXPECT_EQ(load_ok(fine).size(), 1u);
    fine = model("ok.gltf", [](json& doc) { doc["extras"] = json::parse(nested(62)); });
    EXPECT_EQ(load_ok(fine).size(), 1u);
    const std::string deep = model("deep2.gltf", [](json& doc) { doc["extras"] = json::parse(nested(64)); });
    EXPECT_EQ(load_error(deep).rfind("nests its JSON more than 64 levels deep", 0), 0u);
}

TEST_F(GltfHardening, TooManyJsonValuesAreRefused) {
    std::string values = "[0";
    for (int i = 0; i < 1'000'000; ++i) values += ",0";
    std::ofstream(path("many.gltf"), std::ios::binary) << R"({"asset":{"version":"2.0"},"extras":)" << values << "]}";
    EXPECT_EQ(load_error(path("many.gltf")), "has more than 1000000 JSON values");
}

TEST_F(GltfHardening, AByteLengthMismatchNamesByteLengthAndBothSizesWithoutData) {
    const std::string embedded = model("embedded.gltf", [](json& doc) { doc["buffers"][0]["byteLength"] = 40; });
    const std::string message = load_error(embedded);
    EXPECT_EQ(message, "has buffer 0 whose byteLength is 40 bytes, but its data: URI holds 36");
    EXPECT_EQ(message.find("AAAA"), std::string::npos);
    std::vector<unsigned char> bin(36, 0);
    std::ofstream(path("m.bin"), std::ios::binary).write(reinterpret_cast<const char*>(bin.data()), 36);
    const std::string external = model("external.gltf", [](json& doc) {
        doc["buffers"][0] = {{"uri", "m.bin"}, {"byteLength", 48}};
    });
    EXPECT_EQ(load_error(external), "has buffer 0 whose byteLength is 48 bytes, but its file \"m.bin\" holds 36");
    GltfWriter w;
    w.node({{"mesh", w.mesh({{"attributes", {{"POSITION", w.vec3(kTriangle)}}}})}});
    w.write(path("unused.gltf"));
    w.doc["buffers"] = json::array({{{"byteLength", 64}}});
    write_glb(path("short.glb"), w.doc.dump(), w.bin);
    EXPECT_EQ(load_error(path("short.glb")),
              "has buffer 0 whose byteLength is 64 bytes, but the .glb's binary chunk holds 36");
}

TEST_F(GltfHardening, AMissingBufferViewIsNamedWithItsIndex) {
    EXPECT_EQ(load_error(model("view.gltf", [](json& doc) { doc["accessors"][0]["bufferView"] = 7; })),
              "has accessor 0 that refers to bufferView 7, which does not exist (the model has 1 bufferView)");
    // Indices without data (tinygltf said "accessor[1] invalid bufferView").
    GltfWriter w;
    const int indices = w.indices(std::vector<std::uint16_t>{0, 1, 2});
    w.doc["accessors"][indices].erase("bufferView");
    w.node({{"mesh", w.mesh({{"attributes", {{"POSITION", w.vec3(kTriangle)}}}, {"indices", indices}})}});
    w.write(path("indices.gltf"));
    EXPECT_EQ(load_error(path("indices.gltf")),
              "has mesh 0 primitive 0 whose indices accessor 0 has no bufferView (its data is missing)");
    EXPECT_EQ(load_error(model("buffer.gltf", [](json& doc) { doc["bufferViews"][0]["buffer"] = 3; })),
              "has bufferView 0 that refers to buffer 3, which does not exist (the model has 1 buffer)");
}

TEST_F(GltfHardening, HugeNodeTransformsAreRefusedNamingTheNode) {
    const auto with_node = [&](const std::string& name, json fields) {
        return model(name, [&](json& doc) {
            for (auto& [k, v] : fields.items()) doc["nodes"][0][k] = v;
        });
    };
    json matrix = {1e300, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    EXPECT_EQ(load_error(with_node("matrix.gltf", {{"matrix", matrix}})),
              "has node 0 whose matrix holds 1e+300, beyond the scale limit of 1000000");
    EXPECT_EQ(load_error(with_node("scale.gltf", {{"scale", {1e20, 1, 1}}})),
              "has node 0 whose scale holds 1e+20, beyond the scale limit of 1000000");
    EXPECT_EQ(load_error(with_node("move.gltf", {{"translation", {0, 2e5, 0}}})),
              "has node 0 whose translation holds 200000, beyond the 100 km coordinate limit (100000 m)");
    matrix = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 2};
    EXPECT_EQ(load_error(with_node("projective.gltf", {{"matrix", matrix}})),
              "has node 0 whose matrix is not affine (its last row must be 0, 0, 0, 1)");
    // Each scale within the limit, their product beyond 100 km.
    GltfWriter w;
    const int mesh = w.mesh({{"attributes", {{"POSITION", w.vec3(kTriangle)}}}});
    w.node({{"children", {1}}, {"scale", {1000, 1000, 1000}}});
    w.node({{"mesh", mesh}, {"scale", {1000, 1000, 1000}}});
    w.doc["scenes"] = json::array({{{"nodes", {0}}}});
    w.write(path("nested.gltf"));
    EXPECT_EQ(load_error(path("nested.gltf")),
              "has node 1 that places vertex 1 of mesh 0 primitive 0 at (1000000, 0, 0), beyond the 100 km "
              "coordinate limit (100000 m)");
}

TEST_F(GltfHardening, AVertexBeyondOneHundredKilometresIsRefused) {
    GltfWriter w;
    w.node({{"mesh", w.mesh({{"attributes", {{"POSITION", w.vec3({0, 0, 0, 3e38f, 0, 0, 0, 1, 0})}}}})}});
    w.write(path("far.gltf"));
    EXPECT_EQ(
        load_error(path("far.gltf")).rfind("has mesh 0 primitive 0 whose POSITION accessor 0 has vertex 1 at (3", 0),
        0u)
        << load_error(path("far.gltf"));
    EXPECT_NE(load_error(path("far.gltf")).find("beyond the 100 km coordinate limit (100000 m)"), std::string::npos);
}

TEST_F(GltfHardening, ABufferFileThatIsNotARegularFileSaysWhatItIs) {
    fs::create_directories(dir_ / "d.bin");
    const auto with_uri = [&](const std::string& name, const std::string& uri) {
        return model(name, [&](json& doc) { doc["buffers"][0] = {{"uri", uri}, {"byteLength", 36}}; });
    };
    EXPECT_EQ(load_error(with_uri("dir.gltf", "d.bin")),
              "has buffer 0 whose file \"d.bin\" is a directory, not a regular file");
    ASSERT_EQ(::mkfifo(path("f.bin").c_str(), 0600), 0);
    EXPECT_EQ(load_error(with_uri("fifo.gltf", "f.bin")),
              "has buffer 0 whose file \"f.bin\" is a FIFO (named pipe), not a regular file");
    // A device of the test's own (needs root; CI runs as root).
    if (::mknod(path("zero.bin").c_str(), S_IFCHR | 0600, makedev(1, 5)) == 0) {
        EXPECT_EQ(load_error(with_uri("dev.gltf", "zero.bin")),
                  "has buffer 0 whose file \"zero.bin\" is a device, not a regular file");
    }
    // An absolute path lies outside the folder (tinygltf would look for it inside).
    EXPECT_EQ(load_error(with_uri("abs.gltf", "/dev/zero")),
              "has buffer 0 whose file \"/dev/zero\" lies outside the model's folder");
    EXPECT_EQ(load_error(with_uri("up.gltf", "../../../../../../dev/zero")),
              "has buffer 0 whose file \"../../../../../../dev/zero\" lies outside the model's folder");
}

TEST_F(GltfHardening, EveryRequiredExtensionIsNamedDracoIncluded) {
    // A Draco primitive as exporters write it: accessors without bufferViews.
    const std::string draco = model("draco.gltf", [](json& doc) {
        doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
        doc["extensionsRequired"] = {"KHR_draco_mesh_compression", "KHR_mesh_quantization"};
        doc["accessors"][0].erase("bufferView");
        doc["accessors"].push_back({{"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}});
        doc["meshes"][0]["primitives"][0]["indices"] = 1;
        doc["meshes"][0]["primitives"][0]["extensions"] = {
            {"KHR_draco_mesh_compression", {{"bufferView", 0}, {"attributes", {{"POSITION", 0}}}}}};
    });
    EXPECT_EQ(load_error(draco),
              "requires the unsupported glTF extensions \"KHR_draco_mesh_compression\", \"KHR_mesh_quantization\" "
              "(Draco mesh compression; export the model without it)");
    // Used but not required: the model reads without it.
    EXPECT_EQ(load_ok(model("used.gltf", [](json& doc) { doc["extensionsUsed"] = {"KHR_materials_unlit"}; })).size(),
              1u);
}

TEST_F(GltfHardening, AMaterialThatDoesNotExistIsNamed) {
    EXPECT_EQ(load_error(model("material.gltf", [](json& doc) { doc["meshes"][0]["primitives"][0]["material"] = 5; })),
              "has mesh 0 primitive 0 whose material 5 does not exist (the model has 0 materials)");
}

TEST_F(GltfHardening, SparseAccessorsHaveTheirSubstitutionsApplied) {
    GltfWriter w;
    const int positions = w.vec3({0, 0, 0, 9, 9, 9, 0, 1, 0});
    const std::vector<std::uint8_t> at = {1};
    const std::vector<float> value = {1, 0, 0};
    const int at_view = w.view(at.data(), at.size());
    const int value_view = w.view(value.data(), value.size() * sizeof(float));
    w.doc["accessors"][positions]["sparse"] = {{"count", 1},
                                               {"indices", {{"bufferView", at_view}, {"componentType", 5121}}},
                                               {"values", {{"bufferView", value_view}}}};
    // A second triangle from zeros (no bufferView) and a sparse corner.
    const int zeros = int(w.doc["accessors"].size());
    const std::vector<std::uint8_t> at2 = {1, 2};
    const std::vector<float> values2 = {0, 0, 1, 0, 1, 0};
    w.doc["accessors"].push_back({{"componentType", 5126},
                                  {"count", 3},
                                  {"type", "VEC3"},
                                  {"sparse",
                                   {{"count", 2},
                                    {"indices", {{"bufferView", w.view(at2.data(), 2)}, {"componentType", 5121}}},
                                    {"values", {{"bufferView", w.view(values2.data(), 24)}}}}}});
    w.node({{"mesh", w.mesh({{"attributes", {{"POSITION", positions}}}})}});
    w.node({{"mesh", w.mesh({{"attributes", {{"POSITION", zeros}}}})}});
    w.write(path("sparse.gltf"));
    const auto triangles = load_ok(path("sparse.gltf"));
    ASSERT_EQ(triangles.size(), 2u);
    EXPECT_EQ(triangles[0].position[1], glm::dvec3(1, 0, 0));
    EXPECT_EQ(triangles[1].position[0], glm::dvec3(0, 0, 0));
    EXPECT_EQ(triangles[1].position[1], glm::dvec3(0, 0, 1));
    EXPECT_EQ(triangles[1].position[2], glm::dvec3(0, 1, 0));
    // Indices that do not increase are refused.
    w.doc["accessors"][zeros]["sparse"]["indices"]["bufferView"] = w.view(std::vector<std::uint8_t>{2, 1}.data(), 2);
    w.write(path("backwards.gltf"));
    EXPECT_NE(load_error(path("backwards.gltf")).find("sparse index 1 (number 1) is not below 3 or does not increase"),
              std::string::npos);
}

TEST_F(GltfHardening, TriangleStripsAndFansBecomeCounterClockwiseTriangles) {
    // A unit square in z = 0 seen from +z, as a strip and as a fan.
    const std::vector<float> strip = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
    const std::vector<float> fan = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    GltfWriter w;
    w.node({{"mesh", w.mesh({{"attributes", {{"POSITION", w.vec3(strip)}}}, {"mode", 5}})}});
    w.node({{"mesh", w.mesh({{"attributes", {{"POSITION", w.vec3(fan)}}},
                             {"indices", w.indices(std::vector<std::uint8_t>{0, 1, 2, 3})},
                             {"mode", 6}})}});
    w.write(path("strips.gltf"));
    const auto triangles = load_ok(path("strips.gltf"));
    ASSERT_EQ(triangles.size(), 4u);
    for (const ModelTriangle& t : triangles) {
        const glm::dvec3 n = glm::cross(t.position[1] - t.position[0], t.position[2] - t.position[0]);
        EXPECT_NEAR(n.z, 1.0, 1e-12) << "a unit right triangle facing +z";
    }
    EXPECT_EQ(triangles[1].position[0], glm::dvec3(1, 0, 0));  // strip triangle 1: v1, v3, v2
    EXPECT_EQ(triangles[1].position[1], glm::dvec3(1, 1, 0));
    EXPECT_EQ(triangles[3].position[2], glm::dvec3(0, 0, 0));  // fan triangles end at v0
}

TEST_F(GltfHardening, SkinsAndMorphTargetsAreDrawnInTheBindPose) {
    GltfWriter w;
    const int positions = w.vec3(kTriangle);
    const int offsets = w.vec3({5, 5, 5, 5, 5, 5, 5, 5, 5});
    const std::vector<std::uint8_t> joints(12, 0);
    const std::vector<float> weights = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
    const int joint_view = w.view(joints.data(), joints.size());
    w.doc["accessors"].push_back({{"bufferView", joint_view}, {"componentType", 5121}, {"count", 3}, {"type", "VEC4"}});
    const int weight_view = w.view(weights.data(), weights.size() * sizeof(float));
    w.doc["accessors"].push_back(
        {{"bufferView", weight_view}, {"componentType", 5126}, {"count", 3}, {"type", "VEC4"}});
    const int mesh = w.mesh({{"attributes", {{"POSITION", positions}, {"JOINTS_0", 2}, {"WEIGHTS_0", 3}}},
                             {"targets", {{{"POSITION", offsets}}}}});
    w.doc["meshes"][mesh]["weights"] = {1.0};
    w.node({{"mesh", mesh}, {"skin", 0}});
    w.node({{"translation", {0, 3, 0}}});  // the joint, moved from its bind pose
    w.doc["skins"] = json::array({{{"joints", {1}}}});
    w.doc["scenes"] = json::array({{{"nodes", {0, 1}}}});
    w.write(path("skinned.gltf"));
    const auto triangles = load_ok(path("skinned.gltf"));
    ASSERT_EQ(triangles.size(), 1u);
    EXPECT_EQ(triangles[0].position[0], glm::dvec3(0, 0, 0));
    EXPECT_EQ(triangles[0].position[1], glm::dvec3(1, 0, 0));
    EXPECT_EQ(triangles[0].position[2], glm::dvec3(0, 1, 0));
}

}  // namespace
}  // namespace layout_test
