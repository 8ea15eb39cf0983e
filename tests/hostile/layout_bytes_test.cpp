// A NUL byte inside a layout file, after its JSON or within it, is an error
// at its line and column, not the end of the text.
#include <algorithm>

#include "hostile/hostile_util.hpp"

namespace impossible::hostile {
namespace {

class HostileLayoutBytes : public Hostile {};

TEST_F(HostileLayoutBytes, ANulByteDoesNotEndALayout) {
    const std::string layout = slurp(dir_ / "lay.json");
    spit(dir_ / "nul.json", layout + std::string("\0garbage", 8));
    expect_refused(run("$BIN validate nul.json"), 1, "a NUL byte");
    // Where it is: the line and column after the layout's last character.
    const Outcome r = run("$BIN validate nul.json");
    const long lines = std::count(layout.begin(), layout.end(), '\n');
    EXPECT_NE(r.err.find("nul.json:" + std::to_string(lines + 1) + ":1:"), std::string::npos) << r.err;
    spit(dir_ / "inside.json", layout.substr(0, 10) + std::string("\0", 1) + layout.substr(10));
    expect_refused(run("$BIN render inside.json --out x.png"), 1, "inside.json:");
    EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

}  // namespace
}  // namespace impossible::hostile
