// Outputs: what is at the path is written through, never replaced by
// something else; two names for one file are a usage error before any work;
// a failed run leaves nothing behind; every write is checked.
#include "hostile/hostile_util.hpp"

namespace impossible::hostile {
namespace {

const char* kSmall = " --size 32x24";

TEST_F(Hostile, OutputThroughASymlinkWritesItsTargetAndKeepsTheLink) {
    const Outcome r = run("ln -s target.png link.png && $BIN render" + std::string(kSmall) +
                          " --out link.png && test -L link.png && test -f target.png");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(slurp(dir_ / "target.png").substr(1, 3), "PNG");
    EXPECT_EQ(listing(dir_), "lay.json\nlink.png\ntarget.png\n");
}

TEST_F(Hostile, ADanglingSymlinkCreatesItsTarget) {
    const Outcome r = run("mkdir sub && ln -s sub/new.png link.png && $BIN render" + std::string(kSmall) +
                          " --out link.png && test -L link.png && test -f sub/new.png");
    EXPECT_EQ(r.status, 0) << r.err;
}

TEST_F(Hostile, ADeviceIsWrittenNotReplaced) {
    const std::string null = device("null"), full = device("full");
    Outcome r = run("$BIN render" + std::string(kSmall) + " --out " + null + " --ids " + null);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(is_char_device(null));
    // A full device refuses every write: the error must show (it "succeeded" before).
    r = run("$BIN render" + std::string(kSmall) + " --out " + full);
    expect_refused(r, 1, full + ": cannot write: No space left on device");
    EXPECT_TRUE(is_char_device(full));
}

TEST_F(Hostile, StandardOutputAsAnOutputFileWorks) {
    // A link of its own to standard output, like /dev/stdout (which the
    // program before replaced with a file when run as root).
    const Outcome r = run("ln -s /proc/self/fd/1 stdout.png; $BIN render" + std::string(kSmall) +
                          " --out stdout.png | head -c 4 | tail -c 3");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, "PNG");
}

TEST_F(Hostile, ADescriptorByNameIsWrittenWhereItPoints) {
    // /dev/fd/1 (like /dev/stdout) after `>>`: appended, not replacing the
    // file nor writing over its start.
    const Outcome r = run("echo first > f.txt; $BIN render" + std::string(kSmall) + " --out /dev/fd/1 >> f.txt");
    EXPECT_EQ(r.status, 0) << r.err;
    const std::string f = slurp(dir_ / "f.txt");
    EXPECT_EQ(f.substr(0, 10), "first\n\x89PNG");
}

TEST_F(Hostile, ALongOutputNameThatFitsTheLimitWorks) {
    const std::string name = std::string(250, 'n') + ".png";  // 254 characters
    const Outcome r = run("$BIN render" + std::string(kSmall) + " --out " + name);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir_ / name));
}

TEST_F(Hostile, TwoOutputsNamingOneFileAreAUsageError) {
    expect_refused(run("$BIN render --out x.png --ids x.png"), 2, "--ids x.png is the same file as --out x.png");
    expect_refused(run("$BIN render --out x.png --ids ./sub/../x.png"), 2, "is the same file as");
    expect_refused(run("ln -s x.png y.png; $BIN trace --out x.png --ids y.png"), 2, "is the same file as");
    expect_refused(run("$BIN bench --frames 1 --json F --csv F"), 2, "--csv F is the same file as --json F");
    EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

TEST_F(Hostile, AnOutputThatIsAnInputIsAUsageError) {
    const std::string before = slurp(dir_ / "lay.json");
    expect_refused(run("$BIN render lay.json --out lay.json"), 2, "the same file as the layout lay.json");
    expect_refused(run("ln -s lay.json l2.json; $BIN render l2.json --ids lay.json"), 2, "the same file as");
    EXPECT_EQ(slurp(dir_ / "lay.json"), before);
    Outcome r = run("$BIN render" + std::string(kSmall) + " --out a.png && $BIN render" + std::string(kSmall) +
                    " --out b.png && cp a.png a0.png && $BIN compare a.png b.png --diff a.png");
    expect_refused(r, 2, "--diff a.png is the same file as image A a.png");
    EXPECT_EQ(slurp(dir_ / "a.png"), slurp(dir_ / "a0.png"));
    r = run("printf '0 1.6 1 0 0 0\\n' > p.txt; $BIN plan lay.json --path p.txt --out p.txt");
    expect_refused(r, 2, "the same file as --path p.txt");
    r = run("$BIN tour lay.json --out lay.json");
    expect_refused(r, 2, "the same file as the layout");
    EXPECT_EQ(slurp(dir_ / "lay.json"), before);
}

TEST_F(Hostile, AFailedRunLeavesNoFile) {
    expect_refused(run("$BIN render" + std::string(kSmall) + " --out o.png --ids /missing/dir/i.png"), 1,
                   "/missing/dir/i.png: cannot write");
    expect_refused(run("$BIN trace" + std::string(kSmall) + " --out o.png --ids /missing/dir/i.png"), 1,
                   "/missing/dir/i.png: cannot write");
    expect_refused(run("$BIN plan lay.json --out o.svg --png /missing/dir/o.png"), 1, "cannot write");
    const std::string full = device("full");
    expect_refused(run("$BIN render" + std::string(kSmall) + " --out o.png --ids " + full), 1, "No space left");
    expect_refused(run("mkdir -p sub; $BIN render" + std::string(kSmall) + " --out sub"), 1,
                   "sub: cannot write: is a directory");
    fs::remove(dir_ / "full");
    fs::remove(dir_ / "sub");
    EXPECT_EQ(listing(dir_), "lay.json\n");
}

TEST_F(Hostile, BenchWritesBothReportsOrNeither) {
    const Outcome r =
        run("$BIN bench lay.json --size 32x24 --frames 1 --warmup 0 --profile-frames 1 --json x.json "
            "--csv /missing/x.csv",
            120);
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_NE(r.err.find("/missing/x.csv: cannot write"), std::string::npos) << r.err;
    EXPECT_EQ(listing(dir_), "lay.json\n");
}

TEST_F(Hostile, AFullDiskDoesNotTruncateThePreviousFile) {
    // A full device as the second output: the earlier report at x.json is
    // untouched when it fails (written together or not at all).
    const Outcome r =
        run("echo previous > x.json; $BIN bench lay.json --size 32x24 --frames 1 --warmup 0 "
            "--profile-frames 1 --json x.json --csv " +
                device("full"),
            120);
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_EQ(slurp(dir_ / "x.json"), "previous\n");
}

TEST_F(Hostile, FailedWritesToStandardOutputAreErrors) {
    // (validate warns about the default layout's overlapping rooms first)
    const Outcome v = run("$BIN validate lay.json > /dev/full");
    EXPECT_EQ(v.status, 1);
    EXPECT_NE(v.err.find("impossible: cannot write to standard output: No space left on device\n"), std::string::npos)
        << v.err;
    expect_refused(run("printf '0 1.6 1 0 0 0\\n%.0s' {1..3000} > p.txt; $BIN walk lay.json --path p.txt > /dev/full"),
                   1, "cannot write to standard output");
    const Outcome r = run("$BIN render" + std::string(kSmall) + " --out a.png && $BIN compare a.png a.png > /dev/full");
    expect_refused(r, 1, "cannot write to standard output");
    expect_refused(run("$BIN --help > /dev/full"), 1, "cannot write to standard output");
    // A closed standard output that nothing is written to is no error.
    EXPECT_EQ(run("$BIN render" + std::string(kSmall) + " --out a.png >&-").status, 0);
}

}  // namespace
}  // namespace impossible::hostile
