// Issue 38 §4, a new user's findings: numbers read one way on the command
// line and in path files (a subnormal reads as 0, hexadecimal is refused in
// words), a sweep's failed item names the sweep, and compare's flat_* keys
// show a correct frame as correct where interior_max_error counts the
// checker's edges.
#include <string>

#include "hostile/hostile_util.hpp"

namespace impossible::hostile {
namespace {

TEST_F(Hostile, SubnormalNumbersReadAsZero) {
    // 1e-320 is a number (subnormal), not "not a finite number": it reads as
    // 0, in every option and in path files alike.
    EXPECT_EQ(
        run("$BIN render lay.json --size 8x8 --out a.png --room hall --pose 0,1.6,1e-320,0,0,0 --time 1e-320").status,
        0);
    EXPECT_EQ(run("$BIN render lay.json --size 8x8 --out b.png --room hall --pose 0,1.6,0,0,0,0 --time 0").status, 0);
    EXPECT_EQ(slurp(dir_ / "a.png"), slurp(dir_ / "b.png"));
    EXPECT_EQ(run("$BIN render lay.json --size 8x8 --out c.png --fov-angles -50,40,40,-1e-320").status, 0);
    EXPECT_EQ(run("$BIN render lay.json --size 8x8 --out d.png --hands 0,1,0,0,0,1e-400,0,1,0,0,0,0").status, 0);
    spit(dir_ / "p.txt", "0 1.6 1e-320 0 0 0\n");
    const Outcome w = run("$BIN walk lay.json --path p.txt");
    EXPECT_EQ(w.status, 0) << w.err;
    // Too large is still not finite.
    expect_refused(run("$BIN render lay.json --size 8x8 --time 1e400"), 1, "--time: '1e400' is not a finite number");
}

TEST_F(Hostile, HexadecimalIsRefusedEverywhereInWords) {
    expect_refused(run("$BIN render lay.json --size 8x8 --fov 0x40"), 1,
                   "--fov: '0x40' is hexadecimal: write numbers in decimal");
    expect_refused(run("$BIN render lay.json --size 8x8 --pose 0,1.6,0,0,0,-0X1p3"), 1,
                   "--pose: '-0X1p3' is hexadecimal: write numbers in decimal");
    spit(dir_ / "p.txt", "0 1.6 1 0 0 0x10\n");
    expect_refused(run("$BIN walk lay.json --path p.txt"), 1, "p.txt:1: ROLL: '0x10' is hexadecimal");
    expect_refused(run("$BIN render lay.json --size 8x8 --fov ' 64'"), 1, "--fov: ' 64' is not a finite number");
}

TEST_F(Hostile, ASweepItemTheDriverLacksNamesTheSweep) {
    // llvmpipe offers 1 and 4 samples; a driver with 16 measures it.
    const Outcome r = run("$BIN bench lay.json --size 8x8 --frames 1 --sweep samples:16");
    EXPECT_EQ(r.status, 0) << r.err;
    if (r.out.find("not measured") != std::string::npos) {
        EXPECT_NE(r.out.find("samples=16: not measured: --sweep samples 16: the OpenGL driver"), std::string::npos)
            << r.out;
        EXPECT_EQ(r.out.find("--samples 16"), std::string::npos) << r.out;
    }
    // The base configuration's own --samples is still --samples.
    const Outcome base = run("$BIN bench lay.json --size 8x8 --frames 1 --samples 16");
    if (base.status != 0) expect_refused(base, 1, "--samples 16: the OpenGL driver");
}

TEST_F(Hostile, CompareShowsACorrectDefaultFrameAsCorrect) {
    const Outcome r =
        run("$BIN render lay.json --size 320x180 --out r.png --ids ri.png && "
            "$BIN trace lay.json --size 320x180 --out t.png --ids ti.png && "
            "$BIN compare r.png t.png --ids-a ri.png --ids-b ti.png");
    ASSERT_EQ(r.status, 0) << r.err;
    // The keys scripts read stay, in their order; flat_* come after them.
    const std::size_t interior = r.out.find(" interior_max_error=");
    const std::size_t flat = r.out.find(" flat_pixels=");
    ASSERT_NE(interior, std::string::npos) << r.out;
    ASSERT_NE(flat, std::string::npos) << r.out;
    EXPECT_LT(interior, flat);
    const std::size_t at = r.out.find("flat_max_error=");
    ASSERT_NE(at, std::string::npos) << r.out;
    EXPECT_LE(std::stoi(r.out.substr(at + 15)), 8) << r.out;
}

}  // namespace
}  // namespace impossible::hostile
