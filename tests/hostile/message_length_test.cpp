// Messages are cut at about 100 characters: a megabyte key, format or room
// name in a layout, or a 3 MB field of a path file, is refused with a line
// that ends "... (N more bytes)", never with the whole name.
#include "hostile/hostile_util.hpp"

namespace impossible::hostile {
namespace {

class HostileMessageLength : public Hostile {};

// The longest line a refusal of a megabyte name may print.
constexpr std::size_t kShortLine = 400;

TEST_F(HostileMessageLength, LongNamesAreCutInMessages) {
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

}  // namespace
}  // namespace impossible::hostile
