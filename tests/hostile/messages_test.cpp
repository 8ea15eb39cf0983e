// The smaller defects of issue 15: a field of view too narrow to render
// right, PNG faults in words, the walker's teleport cap, follow-on errors,
// a broken GALLIUM_DRIVER, messages that span lines or megabytes (a name or
// field of megabytes is cut at about 100 characters), glTF buffers outside
// the model's folder.
#include "hostile/hostile_util.hpp"
#include "hostile/png_bytes.hpp"

namespace impossible::hostile {
namespace {

bool printable_ascii(const std::string& s) {
    for (unsigned char c : s)
        if (c != '\n' && (c < 0x20 || c > 0x7E)) return false;
    return true;
}

TEST_F(Hostile, AFieldOfViewTooNarrowToRenderIsARangeError) {
    expect_refused(run("$BIN render --fov 1e-6"), 1, "--fov: 1e-6 is not in 1..179 degrees");
    expect_refused(run("$BIN trace --fov 0.5"), 1, "is not in 1..179 degrees");
    // The narrowest accepted view agrees with the tracer, edges and all.
    const std::string view = " --pose 0.9,1.2,0.5,30,-10,0 --room hall --fov 1 --size 64x48";
    const Outcome r = run("$BIN render" + view + " --out r.png --ids ri.png && $BIN trace" + view +
                          " --out t.png --ids ti.png && $BIN compare r.png t.png --ids-a ri.png --ids-b ti.png "
                          "--max-mismatch 0");
    EXPECT_EQ(r.status, 0) << r.err << r.out;
}

TEST_F(Hostile, CompareReadsOnly8BitIdMaps) {
    std::string rows;
    for (int y = 0; y < 2; ++y) rows += std::string(1, '\0') + std::string("\x00\x01\x00\x02", 4);
    spit(dir_ / "ids16.png", png_file(2, 2, 16, 0, rows));
    std::string rows8;
    for (int y = 0; y < 2; ++y) rows8 += std::string(1, '\0') + std::string("\x01\x02", 2);
    spit(dir_ / "ids8.png", png_file(2, 2, 8, 0, rows8));
    std::string rgb;
    for (int y = 0; y < 2; ++y) rgb += std::string(1, '\0') + std::string(6, '\x40');
    spit(dir_ / "c.png", png_file(2, 2, 8, 2, rgb));
    EXPECT_EQ(run("$BIN compare c.png c.png --ids-a ids8.png --ids-b ids8.png").status, 0);
    expect_refused(run("$BIN compare c.png c.png --ids-a ids16.png --ids-b ids8.png"), 1,
                   "ids16.png: a cell-id map must be an 8-bit greyscale PNG (this one is 16-bit)");
}

TEST_F(Hostile, ComparePngFaultsInWords) {
    std::string rgb;
    for (int y = 0; y < 2; ++y) rgb += std::string(1, '\0') + std::string(6, '\x40');
    const std::string good = png_file(2, 2, 8, 2, rgb);
    std::string bad_crc = good;
    bad_crc[bad_crc.find("IDAT") + 12] ^= 0x40;  // a data byte of IDAT
    spit(dir_ / "crc.png", bad_crc);
    expect_refused(run("$BIN compare crc.png crc.png"), 1,
                   "crc.png: has a damaged chunk IDAT (its CRC does not match its data)");
    std::string bad_type = good;
    bad_type.replace(bad_type.find("IDAT"), 4, "\x01\xff\x80\x1b", 4);
    spit(dir_ / "type.png", bad_type);
    Outcome r = run("$BIN compare type.png type.png");
    expect_refused(r, 1, "type.png: has a damaged chunk at byte 33 (its type is not four letters)");
    EXPECT_TRUE(printable_ascii(r.err)) << r.err;
    spit(dir_ / "huge.png", png_file(30000, 30000, 8, 2, std::string(1, '\0')));
    expect_refused(run("$BIN compare huge.png huge.png"), 1, "huge.png: is too large (30000x30000 pixels");
    spit(dir_ / "short.png", good.substr(0, good.size() - 20));
    expect_refused(run("$BIN compare short.png short.png"), 1, "short.png: is truncated");
    spit(dir_ / "text.png", "hello");
    expect_refused(run("$BIN compare text.png text.png"), 1, "text.png: is not a PNG file");
}

TEST_F(Hostile, AWalkThatReachesTheTeleportCapSaysSo) {
    const std::string corridor = q(std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/corridor.json");
    const Outcome r =
        run("printf '0.25 1.6 2 0 0 0\\n0.25 1.6 -900000 0 0 0\\n' > p.txt; $BIN walk " + corridor + " --path p.txt");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err_lines(), 1) << r.err;
    EXPECT_NE(r.err.find("warning: p.txt: frame 1 reached the limit of 64 teleports"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 2);
}

TEST_F(Hostile, ValidateAddsNoFollowOnErrors) {
    std::string rooms;
    for (int i = 0; i <= 10000; ++i)
        rooms += std::string(i ? "," : "") + "{\"id\":\"r" + std::to_string(i) + "\",\"min\":[0,0,0],\"max\":[1,1,1]}";
    spit(dir_ / "many.json",
         "{\"format\":\"impossible-layout\",\"version\":1,\"start\":{\"room\":\"r0\","
         "\"position\":[0.5,0.5,0.5]},\"rooms\":[" +
             rooms + "]}");
    expect_refused(run("$BIN validate many.json"), 1, "rooms: has 10001 entries; at most 10000 are allowed");
    spit(dir_ / "dup.json",
         "{\"format\":\"impossible-layout\",\"version\":1,\"start\":{\"room\":\"a\","
         "\"position\":[0.5,0.5,0.5]},\"rooms\":[{\"id\":\"a\",\"id\":\"b\",\"min\":[0,0,0],"
         "\"max\":[1,1,1]}],\"portals\":[{\"id\":\"p\",\"room\":\"a\",\"center\":[0.5,0.5,0],"
         "\"normal\":[0,0,1],\"width\":0.5,\"height\":0.5,\"target\":\"q\"},"
         "{\"id\":\"q\",\"room\":\"a\",\"center\":[0.5,0.5,1],"
         "\"normal\":[0,0,-1],\"width\":0.5,\"height\":0.5,\"target\":\"p\"}]}");
    expect_refused(run("$BIN validate dup.json"), 1, "rooms[0].id: repeated field");
}

TEST_F(Hostile, ABrokenGalliumDriverIsAnErrorNotACrash) {
    for (const std::string backend : {"", " --backend osmesa", " --backend egl"}) {
        const Outcome r = run("GALLIUM_DRIVER=bogus $BIN render --size 32x24" + backend);
        EXPECT_TRUE(r.status == 0 || r.status == 1) << backend << ": " << r.status << " " << r.err;
        if (r.status == 1) {
            EXPECT_EQ(r.err_lines(), 1) << r.err;
        }
    }
    expect_refused(run("GALLIUM_DRIVER=bogus $BIN render --size 32x24 --backend osmesa"), 1,
                   "GALLIUM_DRIVER='bogus' is not a driver it can use");
}

TEST_F(Hostile, MessagesAreOneLineWithEscapedPathsAndCutNames) {
    expect_refused(run("$BIN render $'a\\nb.json'"), 1, "a\\nb.json");
    expect_refused(run("$BIN validate $'x\\ny.json'"), 1, "x\\ny.json");
    expect_refused(run("$BIN walk lay.json --path $'p\\nq.txt'"), 1, "p\\nq.txt: does not exist");
    const std::string name(4'000'000, 'n');
    std::string layout = slurp(dir_ / "lay.json");
    layout.replace(layout.find('{'), 1, "{\"name\":\"" + name + "\",");
    const size_t old_name = layout.find("\"name\":", 20);
    ASSERT_NE(old_name, std::string::npos);
    layout.replace(old_name, 7, "\"_name\":");
    spit(dir_ / "big.json", layout);
    const Outcome r = run("$BIN validate big.json");
    EXPECT_EQ(r.status, 0) << r.err.substr(0, 300);
    EXPECT_LT(r.out.size(), 2000u);
    EXPECT_NE(r.out.find("more bytes)"), std::string::npos) << r.out.substr(0, 400);
}

// The longest line a refusal of a megabyte name may print.
constexpr std::size_t kShortLine = 400;

TEST_F(Hostile, LongNamesAreCutInMessages) {
    const std::string key(3 << 20, 'k');
    const std::string room_id(1 << 20, 'r');
    spit(dir_ / "key.json", R"({"format": "impossible-layout", "version": 1, ")" + key + R"(": 1, "rooms": []})");
    spit(dir_ / "format.json", R"({"format": ")" + key + R"(", "version": 1, "rooms": []})");
    std::string start = slurp(dir_ / "lay.json");
    start.replace(start.find("\"room\": \"hall\""), 14, "\"room\": \"" + room_id + "\"");
    spit(dir_ / "start.json", start);
    for (const char* file : {"key.json", "format.json", "start.json"}) {
        const Outcome r = run(std::string("$BIN validate ") + file);
        EXPECT_EQ(r.status, 1) << file;
        EXPECT_LT(r.err.size(), 2 * kShortLine) << file << ": " << r.err.substr(0, 300);
        EXPECT_NE(r.err.find("... ("), std::string::npos) << file << ": " << r.err.substr(0, 300);
        EXPECT_NE(r.err.find(" more bytes)"), std::string::npos) << file << ": " << r.err.substr(0, 300);
    }
    // A 3 MB field of a path file.
    spit(dir_ / "p.txt", "0 1.6 " + std::string(3 << 20, '1') + "x 0 0 0\n");
    const Outcome path = run("$BIN walk lay.json --path p.txt");
    EXPECT_EQ(path.status, 1);
    EXPECT_LT(path.err.size(), kShortLine) << path.err.substr(0, 300);
}

TEST_F(Hostile, GltfBuffersMustStayInTheModelsFolder) {
    fs::create_directories(dir_ / "models");
    spit(dir_ / "models/m.gltf",
         R"({"asset":{"version":"2.0"},"buffers":[{"uri":"../../../../../../../../etc/passwd","byteLength":36}],
             "bufferViews":[{"buffer":0,"byteLength":36}],
             "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,1]}],
             "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}]})");
    std::string layout = slurp(dir_ / "lay.json");
    const size_t props = layout.find("\"props\": [");
    ASSERT_NE(props, std::string::npos);
    layout.insert(props + 10, "{\"gltf\":\"models/m.gltf\",\"position\":[0,0,0]},");
    spit(dir_ / "g.json", layout);
    const Outcome r = run("$BIN validate g.json");
    EXPECT_EQ(r.status, 1) << r.out;
    EXPECT_NE(r.err.find("lies outside the model's folder"), std::string::npos) << r.out << r.err;
    EXPECT_EQ((r.out + r.err).find("bytes"), std::string::npos) << r.out << r.err;
}

}  // namespace
}  // namespace impossible::hostile
