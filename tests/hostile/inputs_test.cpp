// Inputs that are not regular files: read with a size limit and an idle
// timeout (IMPOSSIBLE_INPUT_TIMEOUT_MS, 700 ms here), never forever; pipes
// and FIFOs that do send data keep working.
#include "hostile/hostile_util.hpp"

namespace impossible::hostile {
namespace {

TEST_F(Hostile, AFifoNobodyWritesToFailsInsteadOfHanging) {
    for (const std::string command : {"validate fifo", "render fifo --size 32x24", "walk lay.json --path fifo",
                                      "compare fifo fifo", "plan lay.json --out p.svg --path fifo"}) {
        const Outcome r = run("mkfifo fifo; $BIN " + command, 20);
        expect_refused(r, 1, "sent no data");
        EXPECT_LT(r.seconds, 10.0) << command;
        fs::remove(dir_ / "fifo");
    }
    EXPECT_EQ(listing(dir_), "lay.json\n");
}

TEST_F(Hostile, AFifoThatSendsALayoutWorks) {
    // The writer comes after the reader opened the FIFO.
    const Outcome r = run("mkfifo fifo; ( sleep 0.3; cat lay.json > fifo ) & $BIN validate fifo; wait");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("rooms: 2"), std::string::npos) << r.out;
}

TEST_F(Hostile, ProcessSubstitutionWorks) {
    const Outcome r = run("$BIN validate <(cat lay.json) && $BIN walk lay.json --path <(echo '0 1.6 1 0 0 0')");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("\"frame\":0"), std::string::npos) << r.out;
}

TEST_F(Hostile, EndlessDevicesAreTooLargeWithinASecond) {
    // Path files and layouts stop at 4 MiB (well under a second; the bound
    // leaves room for a loaded CI machine); compare reads up to 512 MiB.
    for (const std::string command : {"walk lay.json --path /dev/zero", "validate /dev/zero",
                                      "plan lay.json --out p.svg --path /dev/urandom", "compare /dev/zero /dev/zero"}) {
        const Outcome r = run("$BIN " + command, 60);
        expect_refused(r, 1, "is too large");
        EXPECT_LT(r.seconds, command.rfind("compare", 0) == 0 ? 20.0 : 5.0) << command;
    }
}

TEST_F(Hostile, AnEmptyDeviceIsAnEmptyFile) {
    expect_refused(run("$BIN plan lay.json --out p.svg --path /dev/null"), 1, "holds no poses");
    expect_refused(run("$BIN validate /dev/null"), 1, "/dev/null");
}

TEST_F(Hostile, ADirectoryIsNamedAsOne) {
    expect_refused(run("mkdir -p d; $BIN compare d d"), 1, "d: is a directory");
    expect_refused(run("mkdir -p d; $BIN walk lay.json --path d"), 1, "d: is a directory");
}

// A path file's bad field is quoted with its control bytes written out, so
// an escape sequence in it cannot clear the terminal (found by path_fuzzer).
TEST_F(Hostile, APathFileFieldWithAnEscapeSequenceIsQuotedPrintably) {
    spit(dir_ / "p.txt", "0 1.6 1.0 0 0 0\n0 1.6 \x1b[2J\x1b[31mPWNED 0 0 0\n");
    const Outcome r = run("$BIN walk lay.json --path p.txt");
    expect_refused(r, 1, "p.txt:2: Z: '\\x1b[2J\\x1b[31mPWNED' is not a finite number");
    EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << r.err;
}

}  // namespace
}  // namespace impossible::hostile
