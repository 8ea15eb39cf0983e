// Issue 22's layout fields through the program: a motion path past its key
// limit, a volume that shows its own room and a prop id used twice are one
// line each, at their field, from any command; validate states volumes,
// moving props and a glTF hand.
#include <chrono>

#include "hostile/hostile_util.hpp"

namespace impossible::hostile {
namespace {

// A layout of the rooms a and b (where a is) with `props` in a, `portals`
// and `top` (top-level fields, each followed by a comma).
std::string layout_22(const std::string& top, const std::string& props, const std::string& portals) {
    return "{\"format\":\"impossible-layout\",\"version\":1," + top +
           "\"start\":{\"room\":\"a\",\"position\":[0,1.6,1]},\"rooms\":["
           "{\"id\":\"a\",\"min\":[-2,0,-2],\"max\":[2,3,2],\"props\":[" +
           props + "]},{\"id\":\"b\",\"min\":[-2,0,-2],\"max\":[2,3,2]}],\"portals\":[" + portals + "]}";
}

const std::string kVolume =
    "{\"id\":\"v\",\"room\":\"a\",\"kind\":\"volume\",\"target\":\"b\",\"center\":[0,1,0],\"normal\":[0,0,1],"
    "\"width\":1,\"height\":1,\"depth\":1}";

TEST_F(Hostile, AMotionPathPastItsLimitIsOneLineAndQuick) {
    std::string keys = "[0,0,0,0]";
    for (int i = 1; i <= 10000; ++i) keys += ",[" + std::to_string(i) + ",0,0,0]";
    spit(dir_ / "long.json",
         layout_22("", "{\"box\":{\"min\":[0,0,0],\"max\":[1,1,1]},\"id\":\"p\",\"motion\":{\"path\":[" + keys + "]}}",
                   ""));
    const auto start = std::chrono::steady_clock::now();
    for (const char* command : {"validate", "render --size 32x18 --out x.png", "trace --size 32x18 --out x.png"}) {
        expect_refused(run(std::string("$BIN ") + command + " long.json"), 1,
                       "rooms[0].props[0].motion.path: has 10001 entries; at most 10000 are allowed");
    }
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 20.0);
    EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

TEST_F(Hostile, AVolumeShowingItsOwnRoomIsOneLine) {
    std::string v = kVolume;
    v.replace(v.find("\"target\":\"b\""), 12, "\"target\":\"a\"");
    spit(dir_ / "self.json", layout_22("", "", v));
    expect_refused(run("$BIN render --size 32x18 --out x.png self.json"), 1,
                   "self.json:1:" + std::to_string(layout_22("", "", v).find("\"a\",\"center\"") + 1) +
                       ": portals[0].target: a volume cannot show its own room \"a\"");
    EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

TEST_F(Hostile, APropIdUsedTwiceIsOneLine) {
    const std::string box = "{\"box\":{\"min\":[0,0,0],\"max\":[1,1,1]},\"id\":\"twin\"}";
    spit(dir_ / "twins.json", layout_22("", box + "," + box, ""));
    expect_refused(run("$BIN validate twins.json"), 1,
                   "rooms[0].props[1].id: duplicate prop id \"twin\" (also used by rooms[0].props[0]");
}

TEST_F(Hostile, ValidateStatesVolumesMovingPropsAndHands) {
    const std::string chair = (fs::path(IMPOSSIBLE_SOURCE_DIR) / "layouts/models/chair.glb").string();
    spit(dir_ / "all.json",
         layout_22("\"hands\":{\"gltf\":\"" + chair + "\",\"scale\":0.5},",
                   "{\"box\":{\"min\":[1,0,1],\"max\":[1.5,0.5,1.5]},\"id\":\"p\",\"motion\":{\"path\":[[0,0,0,0],"
                   "[1,-1,0,0]],\"loop\":true}}",
                   kVolume));
    const Outcome r = run("$BIN validate all.json");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("portals: 0\npairs: 0\nvolumes: 1\nmoving props: 1\nhands: the glTF model " + chair +
                         ", scale 0.5\n"),
              std::string::npos)
        << r.out;
    const Outcome j = run("$BIN validate all.json --json");
    EXPECT_EQ(j.status, 0) << j.err;
    EXPECT_NE(j.out.find("\"volumes\": 1,\n    \"moving_props\": 1,\n    \"hands\": {"), std::string::npos) << j.out;
}

}  // namespace
}  // namespace impossible::hostile
