// The small defects of issue 26 (hostile inputs, round three): messages cut
// at about 100 characters, a NUL byte inside a layout, path files with two
// signs, a byte order mark, UTF-16 text or no poses, and help texts that list
// only what a command accepts.
#include <regex>
#include <set>

#include "hostile/hostile_util.hpp"

namespace impossible::hostile {
namespace {

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

TEST_F(Hostile, ANulByteDoesNotEndALayout) {
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

TEST_F(Hostile, PathFilesWithTwoSignsBomsWideTextOrNoPoses) {
    spit(dir_ / "signs.txt", "+-0.3 1.6 1 0 0 0\n");
    expect_refused(run("$BIN walk lay.json --path signs.txt"), 1, "signs.txt:1: X: '+-0.3' is not a finite number");
    spit(dir_ / "bom.txt",
         "\xEF\xBB\xBF"
         "0 1.6 1 0 0 0\n");
    const Outcome bom = run("$BIN walk lay.json --path bom.txt");
    EXPECT_EQ(bom.status, 0) << bom.err;
    EXPECT_NE(bom.out.find("\"frame\":0"), std::string::npos) << bom.out;
    spit(dir_ / "wide.txt", std::string("\xFF\xFE"
                                        "0\0 \0"
                                        "1\0\n\0",
                                        10));
    for (const char* command : {"walk lay.json --path", "plan lay.json --out p.svg --path", "bench lay.json --path"})
        expect_refused(run(std::string("$BIN ") + command + " wide.txt"), 1,
                       "wide.txt: is UTF-16 text; save it as UTF-8 or ASCII");
    spit(dir_ / "none.txt", "# only a comment\n\n");
    for (const char* command : {"walk lay.json --path", "plan lay.json --out p.svg --path", "bench lay.json --path"})
        expect_refused(run(std::string("$BIN ") + command + " none.txt"), 1, "none.txt: the path file holds no poses");
    expect_refused(run("$BIN preview lay.json --path none.txt --frames 1 --screenshots shots"), 1,
                   "none.txt: the path file holds no poses");
    EXPECT_FALSE(fs::exists(dir_ / "p.svg"));
}

// Every option a command's --help names, in its usage lines or its option
// list, is one the command knows (bench once listed --out and --ids, which it
// refused).
TEST_F(Hostile, HelpNamesOnlyOptionsTheCommandAccepts) {
    const std::regex option_name(R"((^|[\s\[|])(--[a-z][a-z0-9-]*))");
    for (const char* command :
         {"render", "trace", "bench", "preview", "walk", "validate", "plan", "tour", "generate", "compare"}) {
        const Outcome help = run(std::string("$BIN ") + command + " --help");
        ASSERT_EQ(help.status, 0) << command;
        // The usage lines and the option list: prose may name other
        // commands' options ("for walk, preview --path and bench --path").
        std::istringstream lines(help.out + help.err);
        std::set<std::string> options;
        for (std::string line; std::getline(lines, line);) {
            const std::size_t first = line.find_first_not_of(' ');
            const bool usage = line.rfind("usage:", 0) == 0;
            if (!usage && (first == 0 || first == std::string::npos || (line[first] != '[' && line[first] != '-')))
                continue;
            for (auto it = std::sregex_iterator(line.begin(), line.end(), option_name); it != std::sregex_iterator();
                 ++it)
                options.insert((*it)[2]);
        }
        options.erase("--help");
        EXPECT_GE(options.size(), 1u) << command;
        // The option and a value (or, for a flag, a layout name), then an
        // option the parser must refuse: parsing fails, no work starts.
        for (const std::string& option : options) {
            const Outcome r = run(std::string("$BIN ") + command + " " + option + " 1 --zzz-end </dev/null");
            EXPECT_EQ(r.status, 2) << command << " " << option << ": " << r.err;
            EXPECT_EQ(r.err.find("unknown option " + option + " ("), std::string::npos)
                << command << " " << option << ": " << r.err;
        }
    }
}

}  // namespace
}  // namespace impossible::hostile
