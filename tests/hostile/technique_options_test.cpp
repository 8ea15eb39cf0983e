// --technique and --texture-from-level (cli.md, "Portal techniques") of
// render, trace, bench and preview: bad values are one line naming the
// option (exit 1), wrong combinations usage errors (exit 2), z-clear's rules
// refused with the option named, and nothing written; trace accepts and
// ignores them.
#include <string>

#include "hostile/hostile_util.hpp"

namespace impossible::hostile {
namespace {

TEST_F(Hostile, TechniqueValuesAreChecked) {
    for (const std::string command : {"render", "trace", "bench"}) {
        const std::string base = "$BIN " + command + " lay.json --size 8x8 ";
        expect_refused(run(base + "--technique portal"), 1, "--technique: 'portal' is not stencil, hybrid or z-clear");
        expect_refused(run(base + "--technique hybrid --texture-from-level -1"), 1,
                       "--texture-from-level: -1 is out of range");
        expect_refused(run(base + "--technique hybrid --texture-from-level 251"), 1,
                       "--texture-from-level: 251 is out of range");
        expect_refused(run(base + "--technique hybrid --texture-from-level x"), 1, "--texture-from-level");
        expect_refused(run(base + "--texture-from-level 1"), 2, "--texture-from-level needs --technique hybrid");
        expect_refused(run(base + "--technique z-clear --texture-from-level 1"), 2,
                       "--texture-from-level needs --technique hybrid");
        expect_refused(run(base + "--technique stencil --portal-texture 0.5"), 2,
                       "--portal-texture needs --technique hybrid");
        expect_refused(run(base + "--technique z-clear --portal-texture 0.5"), 2,
                       "--portal-texture needs --technique hybrid");
        EXPECT_EQ(listing(dir_), "lay.json\n") << command;
    }
    // preview takes them too, checked before any window opens.
    expect_refused(run("$BIN preview lay.json --technique portal"), 1,
                   "--technique: 'portal' is not stencil, hybrid or z-clear");
    expect_refused(run("$BIN preview lay.json --texture-from-level 1"), 2,
                   "--texture-from-level needs --technique hybrid");
    expect_refused(run("$BIN preview lay.json --portal-texture 9"), 1, "--portal-texture: 9 is not in (0, 4]");
}

TEST_F(Hostile, ZClearRefusesWhatItCannotDraw) {
    spit(dir_ / "mirrors.json", slurp(fs::path(IMPOSSIBLE_SOURCE_DIR) / "layouts/mirror_hall.json"));
    const std::string render = "$BIN render lay.json --size 8x8 --technique z-clear ";
    expect_refused(run(render), 1, "--technique z-clear draws one level of doors: --max-depth 8 (give --max-depth 1)");
    expect_refused(run(render + "--max-depth 1 --no-cull"), 1, "--technique z-clear needs each door's rectangle");
    expect_refused(run("$BIN render mirrors.json --size 8x8 --technique z-clear --max-depth 1"), 1,
                   "--technique z-clear draws doors only: the layout has a mirror");
    EXPECT_EQ(listing(dir_), "lay.json\nmirrors.json\n");
    // What it can draw, and trace (the oracle) ignores the technique.
    const Outcome ok = run(render +
                           "--max-depth 1 --out z.png && $BIN trace lay.json --size 8x8 --technique z-clear "
                           "--out t.png && $BIN render lay.json --size 8x8 --technique hybrid "
                           "--texture-from-level 1 --out h.png");
    EXPECT_EQ(ok.status, 0) << ok.err;
    EXPECT_EQ(listing(dir_), "h.png\nlay.json\nmirrors.json\nt.png\nz.png\n");
}

}  // namespace
}  // namespace impossible::hostile
