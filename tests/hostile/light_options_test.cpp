// Lights through the program (cli.md, "Time, hands and lights";
// layout-format.md, "Lights"): --light-depth on a "fixed" layout warns in
// one line and changes nothing else; bad values and bad light fields are
// one-line errors naming the option or FILE:LINE:COL and the field, with no
// output written.
#include <string>

#include "hostile/hostile_util.hpp"

namespace impossible::hostile {
namespace {

TEST_F(Hostile, LightDepthOnAFixedLayoutWarnsAndDrawsTheSameImage) {
    const Outcome plain = run("$BIN render lay.json --size 16x8 --out plain.png");
    ASSERT_EQ(plain.status, 0) << plain.err;
    const Outcome deep = run("$BIN render lay.json --size 16x8 --out deep.png --light-depth 5");
    EXPECT_EQ(deep.status, 0) << deep.err;
    EXPECT_EQ(deep.err, "warning: --light-depth has no effect: lay.json's lighting is \"fixed\"\n");
    EXPECT_EQ(slurp(dir_ / "plain.png"), slurp(dir_ / "deep.png"));
    expect_refused(run("$BIN trace lay.json --size 8x8 --out t.png --light-depth 17"), 1,
                   "--light-depth: 17 is out of range 0..16");
    expect_refused(run("$BIN render lay.json --size 8x8 --out t.png --shadow-size 5000"), 1,
                   "--shadow-size: 5000 is out of range 0..4096");
    EXPECT_EQ(listing(dir_), "deep.png\nlay.json\nplain.png\n");
}

TEST_F(Hostile, ABadLightIsOneErrorAtItsField) {
    std::string text = slurp(dir_ / "lay.json");
    text.replace(text.find("\"version\": 1,"), 13, "\"version\": 1, \"lighting\": \"lights\",");
    const std::size_t rooms = text.find("\"rooms\"");
    const std::size_t room = text.find("\"id\"", rooms);
    text.insert(room, "\"lights\": [ { \"position\": [0, -50, 0], \"intensity\": 3 } ], ");
    spit(dir_ / "lit.json", text);
    const Outcome r = run("$BIN render lit.json --size 8x8 --out x.png");
    expect_refused(r, 1, "lit.json:");
    EXPECT_NE(r.err.find(": rooms[0].lights[0].position: the light at [0, -50, 0] is not strictly inside its room"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

}  // namespace
}  // namespace impossible::hostile
