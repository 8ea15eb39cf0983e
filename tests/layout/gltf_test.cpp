// glTF props: the chair model, small models written by the test (indexed and
// not, node transforms, materials), unsupported or broken files, the prop's
// fields in a layout, and placing model points in the layout.
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "assets/gltf_model.hpp"
#include "gltf_writer.hpp"
#include "layout_test_util.hpp"

namespace layout_test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The triangle (0,0,0), (1,0,0), (0,1,0): counter-clockwise seen from +z.

class GltfTest : public ::testing::Test {
protected:
    fs::path dir;

    void SetUp() override {
        dir = temp_path("gltf_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }

    std::string path(const std::string& name) const { return (dir / name).string(); }

    std::vector<ModelTriangle> load_ok(const std::string& file) {
        auto loaded = impossible::assets::load_gltf_triangles(file, 1000000);
        EXPECT_TRUE(loaded) << (loaded ? "" : loaded.error());
        return loaded ? *loaded : std::vector<ModelTriangle>{};
    }
    std::string load_error(const std::string& file, std::size_t max_triangles = 1000000) {
        const auto loaded = impossible::assets::load_gltf_triangles(file, max_triangles);
        EXPECT_FALSE(loaded);
        return loaded ? "" : loaded.error();
    }
    // One node holding one triangle primitive, then written out.
    std::string one_triangle(const std::string& name, json node_fields = json::object(),
                             json primitive_fields = json::object()) {
        GltfWriter w;
        json primitive = {{"attributes", {{"POSITION", w.vec3(kTriangle)}}}};
        for (auto& [k, v] : primitive_fields.items()) primitive[k] = v;
        json node = {{"mesh", w.mesh(primitive)}};
        for (auto& [k, v] : node_fields.items()) node[k] = v;
        w.node(node);
        w.write(path(name));
        return path(name);
    }
};

void expect_vec_near(const glm::dvec3& got, const glm::dvec3& want, double tolerance = 1e-6) {
    EXPECT_NEAR(got.x, want.x, tolerance) << "y " << got.y << " z " << got.z;
    EXPECT_NEAR(got.y, want.y, tolerance) << "x " << got.x << " z " << got.z;
    EXPECT_NEAR(got.z, want.z, tolerance) << "x " << got.x << " y " << got.y;
}

glm::dvec3 winding_normal(const ModelTriangle& t) {
    return glm::normalize(glm::cross(t.position[1] - t.position[0], t.position[2] - t.position[0]));
}

TEST_F(GltfTest, TheChairLoadsWithItsTwoMaterials) {
    const std::vector<ModelTriangle> chair = load_ok(kChairGlb);
    ASSERT_EQ(chair.size(), 84u);  // 7 boxes of 12 triangles
    int wood = 0, fabric = 0;
    glm::dvec3 lo(1e9), hi(-1e9);
    for (const ModelTriangle& t : chair) {
        if (t.color == glm::dvec3(0.55, 0.35, 0.2)) ++wood;
        if (t.color == glm::dvec3(0.7, 0.12, 0.1)) ++fabric;
        for (int k = 0; k < 3; ++k) {
            lo = glm::min(lo, t.position[k]);
            hi = glm::max(hi, t.position[k]);
            EXPECT_NEAR(glm::length(t.normal[k]), 1.0, 1e-12);
            // Front faces are counter-clockwise: the winding agrees with the normals.
            EXPECT_GT(glm::dot(t.normal[k], winding_normal(t)), 0.999);
        }
    }
    EXPECT_EQ(wood, 72);
    EXPECT_EQ(fabric, 12);
    expect_vec_near(lo, {-0.22, 0.0, -0.22});
    expect_vec_near(hi, {0.22, 0.92, 0.22});
}

TEST_F(GltfTest, TheChairLoadsThroughALayout) {
    const LoadResult r = load_layout_file(kLayoutDir + "/props.json");
    ASSERT_TRUE(r.layout.has_value()) << all_messages(r.errors);
    const std::vector<Prop>& props = r.layout->rooms[0].props;
    ASSERT_EQ(props.size(), 3u);
    ASSERT_TRUE(std::holds_alternative<GltfProp>(props[1]));
    const GltfProp& turned = std::get<GltfProp>(props[1]);
    EXPECT_EQ(turned.path, "../../../layouts/models/chair.glb");
    EXPECT_TRUE(fs::equivalent(turned.resolved_path, kChairGlb));
    EXPECT_EQ(turned.position, glm::dvec3(1, 0, 1));
    EXPECT_EQ(turned.yaw_deg, 90.0);
    EXPECT_EQ(turned.scale, 1.0);
    EXPECT_EQ(turned.triangles.size(), 84u);
    const GltfProp& plain = std::get<GltfProp>(props[2]);
    EXPECT_EQ(plain.position, glm::dvec3(-1, 0, 1));
    EXPECT_EQ(plain.yaw_deg, 0.0);  // defaults
    EXPECT_EQ(plain.scale, 1.0);
    EXPECT_EQ(plain.triangles.size(), 84u);
}

TEST_F(GltfTest, FlatNormalsAndTheDefaultGreyWithoutNormalsOrMaterial) {
    const std::vector<ModelTriangle> t = load_ok(one_triangle("t.gltf"));
    ASSERT_EQ(t.size(), 1u);
    expect_vec_near(t[0].position[1], {1, 0, 0});
    for (int k = 0; k < 3; ++k) EXPECT_EQ(t[0].normal[k], glm::dvec3(0, 0, 1));
    EXPECT_EQ(t[0].color, glm::dvec3(0.8));
}

TEST_F(GltfTest, IndexedPrimitivesOfEveryIndexSize) {
    const std::vector<float> quad = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    for (int size : {1, 2, 4}) {
        GltfWriter w;
        int indices = 0;
        if (size == 1) indices = w.indices(std::vector<std::uint8_t>{0, 1, 2, 0, 2, 3});
        if (size == 2) indices = w.indices(std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3});
        if (size == 4) indices = w.indices(std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3});
        w.node({{"mesh", w.mesh({{"attributes", {{"POSITION", w.vec3(quad)}}}, {"indices", indices}})}});
        const std::string file = path("quad" + std::to_string(size) + ".gltf");
        w.write(file);
        const std::vector<ModelTriangle> t = load_ok(file);
        ASSERT_EQ(t.size(), 2u) << size;
        expect_vec_near(t[1].position[0], {0, 0, 0});
        expect_vec_near(t[1].position[1], {1, 1, 0});
        expect_vec_near(t[1].position[2], {0, 1, 0});
    }
}

TEST_F(GltfTest, NodeTransformsApplyToPositionsAndNormals) {
    // Translation (1,2,3), 90° about +Y, scale 2: (1,0,0) → (2,0,0) → (0,0,-2) → (1,2,1).
    const double h = std::sqrt(0.5);
    GltfWriter w;
    const int normals = w.vec3({0, 0, 1, 0, 0, 1, 0, 0, 1});
    w.node({{"mesh", w.mesh({{"attributes", {{"POSITION", w.vec3(kTriangle)}, {"NORMAL", normals}}}})},
            {"translation", {1, 2, 3}},
            {"rotation", {0, h, 0, h}},
            {"scale", {2, 2, 2}}});
    w.write(path("trs.gltf"));
    const std::vector<ModelTriangle> trs = load_ok(path("trs.gltf"));
    ASSERT_EQ(trs.size(), 1u);
    expect_vec_near(trs[0].position[0], {1, 2, 3});
    expect_vec_near(trs[0].position[1], {1, 2, 1});
    expect_vec_near(trs[0].position[2], {1, 4, 3});
    expect_vec_near(trs[0].normal[0], {1, 0, 0});  // +z turned 90° about +Y

    // The same transform as a column-major matrix.
    const std::string file =
        one_triangle("matrix.gltf", {{"matrix", {0, 0, -2, 0, 0, 2, 0, 0, 2, 0, 0, 0, 1, 2, 3, 1}}});
    const std::vector<ModelTriangle> m = load_ok(file);
    ASSERT_EQ(m.size(), 1u);
    for (int k = 0; k < 3; ++k) expect_vec_near(m[0].position[k], trs[0].position[k]);
}

TEST_F(GltfTest, ChildNodesInheritTheirParentsTransform) {
    GltfWriter w;
    const int mesh = w.mesh({{"attributes", {{"POSITION", w.vec3(kTriangle)}}}});
    w.node({{"translation", {0, 1, 0}}, {"children", {1}}});
    w.node({{"translation", {1, 0, 0}}, {"mesh", mesh}});
    w.doc["scenes"] = json::array({{{"nodes", {0}}}});
    w.write(path("tree.gltf"));
    const std::vector<ModelTriangle> t = load_ok(path("tree.gltf"));
    ASSERT_EQ(t.size(), 1u);
    expect_vec_near(t[0].position[0], {1, 1, 0});
}

TEST_F(GltfTest, MirroringNodesKeepFrontFacesCounterClockwise) {
    const std::vector<ModelTriangle> t = load_ok(one_triangle("mirror.gltf", {{"scale", {-1, 1, 1}}}));
    ASSERT_EQ(t.size(), 1u);
    expect_vec_near(winding_normal(t[0]), {0, 0, 1});
    expect_vec_near(t[0].normal[0], {0, 0, 1});
}

TEST_F(GltfTest, TheMaterialsBaseColourFactor) {
    GltfWriter w;
    w.doc["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorFactor", {0.1, 0.2, 0.3, 0.5}}}}}});
    w.node({{"mesh", w.mesh({{"attributes", {{"POSITION", w.vec3(kTriangle)}}}, {"material", 0}})}});
    w.write(path("red.gltf"));
    EXPECT_EQ(load_ok(path("red.gltf"))[0].color, glm::dvec3(0.1, 0.2, 0.3));
}

TEST_F(GltfTest, UnsupportedOrBrokenModelsGiveClearErrors) {
    EXPECT_EQ(load_error(one_triangle("lines.gltf", {}, {{"mode", 1}})),
              "has mesh 0 primitive 0 in mode 1 (lines); only triangles, triangle strips and fans (modes 4, 5, 6) "
              "are supported");
    EXPECT_EQ(load_error(one_triangle("noposition.gltf", {}, {{"attributes", {{"NORMAL", 0}}}})),
              "has mesh 0 primitive 0 without POSITION");
    {
        GltfWriter w;
        w.node({{"mesh", w.mesh({{"attributes", {{"POSITION", w.vec3(kTriangle)}}},
                                 {"indices", w.indices(std::vector<std::uint16_t>{0, 1, 7})}})}});
        w.write(path("badindex.gltf"));
        EXPECT_EQ(load_error(path("badindex.gltf")), "has an index 7 past the end of its 3 vertices");
    }
    {
        GltfWriter w;
        const int positions = w.vec3(kTriangle);
        w.doc["accessors"][positions]["count"] = 4000000000u;
        w.node({{"mesh", w.mesh({{"attributes", {{"POSITION", positions}}}})}});
        w.write(path("overrun.gltf"));
        EXPECT_EQ(load_error(path("overrun.gltf")),
                  "has mesh 0 primitive 0 whose POSITION accessor 0 reaches past the end of its bufferView 0");
    }
    {
        GltfWriter w;
        w.node({{"mesh", w.mesh({{"attributes", {{"POSITION", w.vec3(kTriangle, 5123)}}}})}});
        w.write(path("shorts.gltf"));
        EXPECT_EQ(load_error(path("shorts.gltf")),
                  "has mesh 0 primitive 0 whose POSITION accessor 0 has the unsupported component type 5123");
    }
    {
        GltfWriter w;
        w.node({{"mesh", w.mesh({{"attributes", {{"POSITION", w.vec3({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0})}}}})}});
        w.write(path("four.gltf"));
        EXPECT_EQ(load_error(path("four.gltf")), "has mesh 0 primitive 0 whose vertex count 4 is not a multiple of 3");
    }
    {
        GltfWriter w;
        const int mesh = w.mesh({{"attributes", {{"POSITION", w.vec3(kTriangle)}}}});
        w.node({{"children", {1}}, {"mesh", mesh}});
        w.node({{"children", {0}}});
        w.doc["scenes"] = json::array({{{"nodes", {0}}}});
        w.write(path("cycle.gltf"));
        EXPECT_EQ(load_error(path("cycle.gltf")), "reaches node 0 twice (its nodes must form a tree)");
    }
    {
        GltfWriter w;
        w.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
        w.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
        w.node({{"mesh", w.mesh({{"attributes", {{"POSITION", w.vec3(kTriangle)}}}})}});
        w.write(path("draco.gltf"));
        EXPECT_EQ(load_error(path("draco.gltf")),
                  "requires the unsupported glTF extension \"KHR_draco_mesh_compression\" (Draco mesh compression; "
                  "export the model without it)");
    }
    EXPECT_EQ(load_error(one_triangle("capped.gltf"), 0), "has more than 0 triangles");
}

TEST_F(GltfTest, FilesThatAreNotGltf) {
    std::ofstream(path("junk.glb"), std::ios::binary) << "this is not a binary glTF file at all";
    EXPECT_EQ(load_error(path("junk.glb")).rfind("is not a valid glTF 2.0 file: ", 0), 0u);
    std::ofstream(path("junk.gltf"), std::ios::binary) << "{\"asset\": ";
    EXPECT_EQ(load_error(path("junk.gltf")).rfind("is not a valid glTF 2.0 file: ", 0), 0u);
    std::ofstream(path("empty.glb"), std::ios::binary).flush();
    EXPECT_EQ(load_error(path("empty.glb")).rfind("is not a valid glTF 2.0 file: ", 0), 0u)
        << load_error(path("empty.glb"));
    // A valid header whose chunk lengths point past the end.
    std::vector<unsigned char> chair;
    {
        std::ifstream in(kChairGlb, std::ios::binary);
        chair.assign(std::istreambuf_iterator<char>(in), {});
    }
    ASSERT_GT(chair.size(), 100u);
    std::ofstream(path("cut.glb"), std::ios::binary).write(reinterpret_cast<const char*>(chair.data()), 100);
    EXPECT_EQ(load_error(path("cut.glb")).rfind("is not a valid glTF 2.0 file: ", 0), 0u);
    std::ofstream(path("chair.obj"), std::ios::binary) << "v 0 0 0";
    EXPECT_EQ(load_error(path("chair.obj")), "is not a glTF model (expected a .glb or .gltf file)");
    EXPECT_EQ(load_error(path("missing.glb")), "does not exist");
    fs::create_directories(path("folder.glb"));
    EXPECT_EQ(load_error(path("folder.glb")), "is a directory");
    {
        GltfWriter w;
        w.node({{"mesh", w.mesh({{"attributes", {{"POSITION", w.vec3(kTriangle)}}}})}});
        w.write(path("external.gltf"));
        w.doc["buffers"][0]["uri"] = "missing.bin";
        std::ofstream(path("external.gltf"), std::ios::binary) << w.doc.dump();
        EXPECT_EQ(load_error(path("external.gltf")), "has buffer 0 whose file \"missing.bin\" does not exist");
    }
}

TEST_F(GltfTest, AModelIsNotLoadedFromADevice) {
    EXPECT_EQ(load_error("/dev/zero.glb"), "does not exist");
    EXPECT_FALSE(impossible::assets::load_gltf_triangles("/dev/null", 10));
}

// A layout with one glTF prop: `fields` go inside the prop.
std::string layout_with_prop(const std::string& fields) {
    return "{ \"format\": \"impossible-layout\", \"version\": 1,\n"
           "  \"start\": { \"room\": \"r\", \"position\": [0, 1.6, 0] },\n"
           "  \"rooms\": [ { \"id\": \"r\", \"min\": [-2, 0, -2], \"max\": [2, 3, 2],\n"
           "    \"props\": [ { " +
           fields + " } ] } ] }\n";
}

TEST_F(GltfTest, PropFieldsInALayout) {
    const std::string chair = "\"gltf\": \"../../../layouts/models/chair.glb\"";
    expect_valid(layout_with_prop(chair + ", \"position\": [0, 0, 0], \"yaw_deg\": -45, \"scale\": 0.5"));
    expect_one_error(layout_with_prop(chair + ", \"scale\": 0"), "0 }",
                     "rooms[0].props[0].scale: must be greater than 0 (got 0)");
    expect_one_error(layout_with_prop(chair + ", \"scale\": 1e9"), "1e9",
                     "rooms[0].props[0].scale: 1000000000 is too large (the maximum is 1000000)");
    expect_one_error(layout_with_prop(chair + ", \"yaw_deg\": \"left\""), "\"left\"",
                     "rooms[0].props[0].yaw_deg: must be a number (got a string)");
    expect_one_error(layout_with_prop(chair + ", \"position\": [0, 0]"), "[0, 0]",
                     "rooms[0].props[0].position: must be an array of 3 numbers");
    expect_one_error(layout_with_prop(chair + ", \"color\": [1, 0, 0]"), "\"color\"",
                     "rooms[0].props[0].color: unknown field \"color\"");
    expect_one_error(layout_with_prop("\"gltf\": 3"), "3 }", "rooms[0].props[0].gltf: must be a string (got a number)");
    expect_one_error(layout_with_prop("\"gltf\": \"\""), "\"\" }",
                     "rooms[0].props[0].gltf: must name a .glb or .gltf file (got an empty path)");
    expect_one_error(layout_with_prop("\"gltf\": \"a\\nb.glb\""), "\"a\\nb",
                     "rooms[0].props[0].gltf: the path \"a\\x0ab.glb\" contains a control character");
    const std::string missing = layout_with_prop("\"gltf\": \"models/missing.glb\"");
    expect_one_error(missing, "\"models/missing.glb\"",
                     "rooms[0].props[0].gltf: the model \"" + kLayoutDir + "/models/missing.glb\" does not exist");
    expect_one_error(layout_with_prop("\"gltf\": \"two_rooms.json\""), "\"two_rooms.json\"",
                     "rooms[0].props[0].gltf: the model \"" + kLayoutDir +
                         "/two_rooms.json\" is not a glTF model (expected a .glb or .gltf file)");
}

TEST_F(GltfTest, AbsoluteModelPathsWork) {
    const Layout layout = expect_valid(layout_with_prop("\"gltf\": \"" + kChairGlb + "\""));
    EXPECT_EQ(std::get<GltfProp>(layout.rooms[0].props[0]).resolved_path, kChairGlb);
}

TEST(GltfPlacement, ScaleThenYawThenMove) {
    GltfProp prop;
    prop.position = {1, 0, 1};
    prop.yaw_deg = 90;
    prop.scale = 2;
    // (1,0,0) → (2,0,0) → 90° counter-clockwise seen from above: (0,0,-2) → (1,0,-1).
    expect_vec_near(place_model_point(prop, {1, 0, 0}), {1, 0, -1}, 1e-12);
    expect_vec_near(place_model_point(prop, {0, 1, 0}), {1, 2, 1}, 1e-12);
    // The model's forward -Z turns left to -X, as the head's yaw does.
    expect_vec_near(place_model_normal(prop, {0, 0, -1}), {-1, 0, 0}, 1e-12);
    expect_vec_near(place_model_normal(prop, {0, 3, 0}), {0, 1, 0}, 1e-12);
    prop.yaw_deg = 0;
    prop.scale = 1;
    prop.position = {0, 0, 0};
    EXPECT_EQ(place_model_point(prop, {0.25, 0.5, -0.75}), glm::dvec3(0.25, 0.5, -0.75));
}

}  // namespace
}  // namespace layout_test
