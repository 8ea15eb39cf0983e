// Hostile glTF props through the program: a model whose JSON nests 20 000
// levels deep (it crashed tinygltf inside validate, render and trace) and a
// buffer file that is a FIFO (tinygltf said "file not found") end in one
// line naming the model, with exit status 1.
#include "hostile/hostile_util.hpp"

namespace impossible::hostile {
namespace {

class HostileGltf : public Hostile {
protected:
    // g.json: lay.json with a prop showing models/`model`.
    void layout_with(const std::string& model) {
        std::string layout = slurp(dir_ / "lay.json");
        const size_t props = layout.find("\"props\": [");
        ASSERT_NE(props, std::string::npos);
        layout.insert(props + 10, "{\"gltf\":\"models/" + model + "\",\"position\":[0,0,0]},");
        spit(dir_ / "g.json", layout);
    }
};

TEST_F(HostileGltf, JsonNestedTwentyThousandDeepIsAnErrorNotACrash) {
    fs::create_directories(dir_ / "models");
    spit(dir_ / "models/deep.gltf",
         R"({"asset":{"version":"2.0"},"extras":)" + std::string(20'000, '[') + std::string(20'000, ']') + "}");
    layout_with("deep.gltf");
    for (const std::string command :
         {"validate g.json", "render g.json --size 32x24 --out o.png", "trace g.json --size 32x24 --out o.png"}) {
        const Outcome r = run("$BIN " + command);
        expect_refused(r, 1, "deep.gltf\" nests its JSON more than 64 levels deep");
    }
}

TEST_F(HostileGltf, ABufferThatIsAFifoIsNamedAsOne) {
    fs::create_directories(dir_ / "models");
    spit(dir_ / "models/m.gltf",
         R"({"asset":{"version":"2.0"},"buffers":[{"uri":"m.bin","byteLength":36}],
             "bufferViews":[{"buffer":0,"byteLength":36}],
             "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}],
             "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}]})");
    layout_with("m.gltf");
    const Outcome r = run("mkfifo models/m.bin; $BIN validate g.json");
    expect_refused(r, 1, "has buffer 0 whose file \"m.bin\" is a FIFO (named pipe), not a regular file");
    EXPECT_LT(r.seconds, 5.0);
}

}  // namespace
}  // namespace impossible::hostile
