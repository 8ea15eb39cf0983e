// Real glTF lamps through the program (issue 38 §1): a model with alphaMode
// BLEND materials, a light below the floor and a directional light loads;
// validate, render and trace print the same one warning line for each; a
// bad "blend" is one FILE:LINE:COLUMN error; --exposure 0 draws the image of
// no option, and a bad --exposure names the option.
#include <algorithm>
#include <sstream>
#include <string>

#include "common/lamp_model.hpp"
#include "hostile/hostile_util.hpp"

namespace impossible::hostile {
namespace {

class HostileLamps : public Hostile {
protected:
    // lamp.json: lay.json, lit, with the lamp (models/lamp.gltf) in the hall
    // at the origin and `fields` added to its prop; `top` at the top.
    void lamp_layout(const std::string& fields = "", const std::string& top = "\"lighting\": \"lights\",") {
        fs::create_directories(dir_ / "models");
        test::write_lamp_model((dir_ / "models/lamp.gltf").string());
        std::string text = slurp(dir_ / "lay.json");
        text.replace(text.find("\"version\": 1,"), 13, "\"version\": 1, " + top);
        const std::size_t props = text.find("\"props\": [");
        text.insert(props + 10, "{ \"gltf\": \"models/lamp.gltf\", \"position\": [0, 0, 0]" + fields + " },");
        spit(dir_ / "lamp.json", text);
        const std::size_t at = props + 10;
        const std::size_t line_start = text.rfind('\n', at) + 1;
        prop_at = "lamp.json:" + std::to_string(1 + std::count(text.begin(), text.begin() + long(at), '\n')) + ":" +
                  std::to_string(at - line_start + 1);
    }
    std::string prop_at;  // "lamp.json:LINE:COLUMN" of the lamp's prop
};

// The lines of `text` that start with `start` (validate's findings, such as
// the rooms' overlap, are left out).
std::string lines_starting(const std::string& text, const std::string& start) {
    std::istringstream in(text);
    std::string line, out;
    while (std::getline(in, line))
        if (line.rfind(start, 0) == 0) out += line + "\n";
    return out;
}

TEST_F(HostileLamps, ValidateRenderAndTracePrintTheSameWarnings) {
    lamp_layout();
    const Outcome v = run("$BIN validate lamp.json");
    ASSERT_EQ(v.status, 0) << v.err;
    const std::string at = "warning: " + prop_at + ": rooms[0].props[0]: the model \"models/lamp.gltf\"";
    const std::string want = lines_starting(v.err, at);
    EXPECT_EQ(want, at +
                        " has material 0 (\"Glass\") with alphaMode \"BLEND\", drawn alpha-tested at 0.5 (set the "
                        "prop's \"blend\" to \"mask\" or \"opaque\" to choose)\n" +
                        at +
                        " has material 1 (\"Frosted\") with alphaMode \"BLEND\", drawn alpha-tested at 0.5 (set "
                        "the prop's \"blend\" to \"mask\" or \"opaque\" to choose)\n" +
                        at +
                        "'s directional light \"Sun\" (light 2, node 4 \"SunNode\") is dropped (a layout's "
                        "lights are point and spot lights; the prop's \"lights\": false drops all of its "
                        "lights)\n" +
                        at +
                        "'s light \"Point.002\" (light 1, node 3 \"Fill\") stands at [0, -1, 0], not strictly "
                        "inside the room \"hall\": it is dropped\n");
    EXPECT_NE(v.out.find("hall: 1 light"), std::string::npos) << v.out;
    const Outcome r = run("$BIN render lamp.json --size 16x8 --out r.png");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(lines_starting(r.err, "warning: "), want);
    const Outcome t = run("$BIN trace lamp.json --size 16x8 --out t.png");
    EXPECT_EQ(t.status, 0) << t.err;
    EXPECT_EQ(lines_starting(t.err, "warning: "), want);
    // "lights": false and a chosen "blend" silence them all.
    lamp_layout(", \"blend\": \"opaque\", \"lights\": false");
    const Outcome quiet = run("$BIN render lamp.json --size 16x8 --out q.png");
    EXPECT_EQ(quiet.status, 0) << quiet.err;
    EXPECT_EQ(quiet.err, "");
}

TEST_F(HostileLamps, ABadBlendIsOneErrorAtItsValue) {
    lamp_layout(", \"blend\": \"add\"");
    const Outcome r = run("$BIN render lamp.json --size 8x8 --out x.png");
    expect_refused(r, 1, "lamp.json:");
    EXPECT_NE(r.err.find(": rooms[0].props[0].blend: must be \"mask\" or \"opaque\" (got \"add\")"), std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

TEST_F(HostileLamps, ExposureZeroIsTheImageWithoutItAndBadValuesNameTheOption) {
    for (const char* command : {"render", "trace"}) {
        const std::string bin = std::string("$BIN ") + command + " lay.json --size 16x8 --out " + command;
        ASSERT_EQ(run(bin + "_a.png").status, 0);
        ASSERT_EQ(run(bin + "_b.png --exposure 0").status, 0);
        EXPECT_EQ(slurp(dir_ / (std::string(command) + "_a.png")), slurp(dir_ / (std::string(command) + "_b.png")));
        ASSERT_EQ(run(bin + "_c.png --exposure 1").status, 0);
        EXPECT_NE(slurp(dir_ / (std::string(command) + "_a.png")), slurp(dir_ / (std::string(command) + "_c.png")));
        expect_refused(run(bin + "_d.png --exposure 21"), 1, "--exposure: 21 is out of range -20..20");
        expect_refused(run(bin + "_d.png --exposure x"), 1, "--exposure");
    }
    // The layout's "exposure" is the default that --exposure replaces.
    std::string text = slurp(dir_ / "lay.json");
    text.replace(text.find("\"version\": 1,"), 13, "\"version\": 1, \"exposure\": 1,");
    spit(dir_ / "bright.json", text);
    ASSERT_EQ(run("$BIN render bright.json --size 16x8 --out e.png").status, 0);
    EXPECT_EQ(slurp(dir_ / "render_c.png"), slurp(dir_ / "e.png"));
    ASSERT_EQ(run("$BIN render bright.json --size 16x8 --out f.png --exposure 0").status, 0);
    EXPECT_EQ(slurp(dir_ / "render_a.png"), slurp(dir_ / "f.png"));
}

}  // namespace
}  // namespace impossible::hostile
