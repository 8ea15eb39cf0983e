// Issue 26, defect 1: an output that names a file the command reads (the
// layout's textures, its glTF models and their buffers and images, a path
// file) is a usage error before any work, under any name, link or `..`
// spelling; the file is left byte for byte and the layout still loads.
// Before, only the layout file itself was checked: `render gallery.json
// --out gallery/brick.png` replaced the texture.
#include <cstring>
#include <map>

#include "hostile/hostile_util.hpp"

namespace impossible::hostile {
namespace {

class HostileOverInputs : public Hostile {
protected:
    void SetUp() override {
        Hostile::SetUp();
        const fs::path layouts = fs::path(IMPOSSIBLE_SOURCE_DIR) / "layouts";
        fs::copy_file(layouts / "gallery.json", dir_ / "gallery.json");
        fs::copy(layouts / "gallery", dir_ / "gallery", fs::copy_options::recursive);
        for (const auto& e : fs::recursive_directory_iterator(dir_))
            if (e.is_regular_file()) before_[e.path()] = slurp(e.path());
    }
    // m.json: lay.json with a prop showing models/m.gltf, a one-triangle
    // model whose buffer is the file m.bin and whose texture is tex.png.
    void gltf_with_files() {
        fs::create_directories(dir_ / "models");
        const float data[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1};  // POSITION, then TEXCOORD_0
        std::string bin(sizeof data, '\0');
        std::memcpy(bin.data(), data, sizeof data);
        spit(dir_ / "models/m.bin", bin);
        fs::copy_file(dir_ / "gallery/brick.png", dir_ / "models/tex.png");
        spit(dir_ / "models/m.gltf",
             R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":60,"uri":"m.bin"}],)"
             R"("bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":24}],)"
             R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},)"
             R"({"bufferView":1,"componentType":5126,"count":3,"type":"VEC2"}],)"
             R"("meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1},"material":0}]}],)"
             R"("materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}}],)"
             R"("textures":[{"source":0}],"images":[{"uri":"tex.png"}],"nodes":[{"mesh":0}]})");
        std::string layout = slurp(dir_ / "lay.json");
        const size_t props = layout.find("\"props\": [");
        ASSERT_NE(props, std::string::npos);
        layout.insert(props + 10, R"({"gltf":"models/m.gltf","position":[0,0,0]},)");
        spit(dir_ / "m.json", layout);
        for (const char* name : {"models/m.bin", "models/tex.png", "models/m.gltf", "m.json"})
            before_[dir_ / name] = slurp(dir_ / name);
        ASSERT_EQ(run("$BIN validate m.json").status, 0);
    }
    // Refused with a usage error naming the output and the file it would
    // overwrite; every file of the test is as it was and both layouts load.
    void expect_kept(const std::string& command, const std::string& words) {
        SCOPED_TRACE(command);
        const Outcome r = run("$BIN " + command);
        expect_refused(r, 2, words);
        EXPECT_NE(r.err.find("; it would be overwritten"), std::string::npos) << r.err;
        for (const auto& [path, bytes] : before_) EXPECT_TRUE(slurp(path) == bytes) << path << " changed";
        EXPECT_EQ(run("$BIN validate gallery.json").status, 0);
        if (fs::exists(dir_ / "m.json")) {
            EXPECT_EQ(run("$BIN validate m.json").status, 0);
        }
    }
    std::map<fs::path, std::string> before_;
};

TEST_F(HostileOverInputs, RenderOverATextureIsAUsageError) {
    expect_kept("render gallery.json --size 32x24 --out gallery/brick.png",
                "--out gallery/brick.png is the same file as the texture gallery/brick.png");
    expect_kept("render gallery.json --size 32x24 --out x.png --ids gallery/tiles.png",
                "--ids gallery/tiles.png is the same file as the texture gallery/tiles.png");
    EXPECT_FALSE(fs::exists(dir_ / "x.png"));
    // Other names beside the assets are written.
    const Outcome r = run("$BIN render gallery.json --size 32x24 --out gallery/new.png --ids g.png");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(slurp(dir_ / "gallery/new.png").substr(1, 3), "PNG");
    for (const auto& [path, bytes] : before_) EXPECT_TRUE(slurp(path) == bytes) << path << " changed";
}

TEST_F(HostileOverInputs, TraceOverAGlbModelIsAUsageError) {
    expect_kept("trace gallery.json --size 32x24 --out gallery/crate.glb",
                "--out gallery/crate.glb is the same file as the glTF model gallery/crate.glb");
    expect_kept("trace gallery.json --size 32x24 --out x.png --ids gallery/wood.png", "the texture gallery/wood.png");
}

TEST_F(HostileOverInputs, TheBufferAndImageFilesOfAGltfAreInputs) {
    gltf_with_files();
    expect_kept("render m.json --size 32x24 --out models/m.bin", "a file of the glTF model models/m.gltf: ");
    expect_kept("trace m.json --size 32x24 --out x.png --ids models/tex.png", "/models/tex.png; it would be");
    expect_kept("render m.json --size 32x24 --out models/m.gltf", "the glTF model models/m.gltf");
}

TEST_F(HostileOverInputs, PlanOverATextureIsAUsageError) {
    expect_kept("plan gallery.json --out gallery/mural.png", "--out gallery/mural.png is the same file as the texture");
    expect_kept("plan gallery.json --out x.svg --png gallery/wood.png",
                "--png gallery/wood.png is the same file as the texture");
}

TEST_F(HostileOverInputs, TourOverAModelIsAUsageError) {
    expect_kept("tour gallery.json --out gallery/cutout.glb", "--out gallery/cutout.glb is the same file as the glTF");
}

TEST_F(HostileOverInputs, BenchReportsOverAssetsAreUsageErrors) {
    expect_kept("bench gallery.json --size 32x24 --frames 1 --warmup 0 --profile-frames 1 --json gallery/brick.png",
                "--json gallery/brick.png is the same file as the texture");
    expect_kept(
        "bench gallery.json --size 32x24 --frames 1 --warmup 0 --profile-frames 1 --csv gallery/double_sided.glb",
        "--csv gallery/double_sided.glb is the same file as the glTF model");
}

// bench --hmd p.json --json p.json replaced the profile with bench's JSON
// and exited 0; render refused it. The profile is an input of every command.
TEST_F(HostileOverInputs, BenchReportsOverTheHeadsetProfileAreUsageErrors) {
    fs::copy_file(fs::path(IMPOSSIBLE_SOURCE_DIR) / "profiles/htc-vive.json", dir_ / "p.json");
    before_[dir_ / "p.json"] = slurp(dir_ / "p.json");
    for (const char* output : {"--json", "--csv"})
        expect_kept(std::string("bench gallery.json --hmd p.json --size 32x24 --frames 1 --warmup 0 "
                                "--profile-frames 1 ") +
                        output + " p.json",
                    std::string(output) + " p.json is the same file as --hmd");
    expect_kept("render gallery.json --hmd p.json --size 32x24 --out p.json", "--out p.json is the same file as --hmd");
}

TEST_F(HostileOverInputs, EverySpellingOfAnAssetIsRefused) {
    ASSERT_EQ(
        run("ln -s gallery/brick.png link.png && ln -s gallery g && ln gallery/wood.png hard.png && mkdir sub").status,
        0);
    before_[dir_ / "hard.png"] = slurp(dir_ / "hard.png");
    expect_kept("render gallery.json --size 32x24 --out link.png", "--out link.png is the same file as the texture");
    expect_kept("render gallery.json --size 32x24 --out g/tiles.png", "--out g/tiles.png is the same file as");
    expect_kept("render gallery.json --size 32x24 --out sub/../gallery/mural.png", "--out sub/../gallery/mural.png");
    expect_kept("render gallery.json --size 32x24 --out \"$PWD/gallery/brick.png\"", "/gallery/brick.png is the");
    expect_kept("render gallery.json --size 32x24 --out hard.png", "--out hard.png is the same file as the texture");
    // The layout by other names: its textures are found under them.
    expect_kept("render g/../gallery.json --size 32x24 --out ./gallery/./brick.png", "--out ./gallery/./brick.png");
    expect_kept("render \"$PWD/gallery.json\" --size 32x24 --out g/brick.png",
                "--out g/brick.png is the same file as the texture /");
}

TEST_F(HostileOverInputs, PreviewScreenshotsOverAPathFileAreRefused) {
    // frames.jsonl in the screenshot folder is a hard link of the path file
    // (and frame-0000.png one of a texture): preview would truncate them.
    ASSERT_EQ(run("printf '0 1.6 1 0 0 0\\n' > p.txt && mkdir shots && ln p.txt shots/frames.jsonl").status, 0);
    before_[dir_ / "p.txt"] = slurp(dir_ / "p.txt");
    expect_kept("preview lay.json --path p.txt --frames 1 --screenshots shots",
                "--screenshots shots/frames.jsonl is the same file as --path p.txt");
    ASSERT_EQ(run("rm shots/frames.jsonl && ln gallery/brick.png shots/frame-0000.png").status, 0);
    expect_kept("preview gallery.json --path p.txt --frames 1 --screenshots shots",
                "--screenshots shots/frame-0000.png is the same file as the texture gallery/brick.png");
}

}  // namespace
}  // namespace impossible::hostile
