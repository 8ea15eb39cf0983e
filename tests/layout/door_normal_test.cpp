// A door in a wall whose normal points out of its room (issue 38): it makes
// no hole and stands free, hidden in the wall, so the loader warns at its
// `normal` with the normal to write instead; a loud warning, which render,
// trace, plan and tour print too. Every layout of the project loads without it.
#include <filesystem>

#include "layout_test_util.hpp"

namespace layout_test {
namespace {

std::string with_door(const std::string& center, const std::string& normal) {
    return R"({
  "format": "impossible-layout", "version": 1,
  "start": { "room": "r", "position": [0, 1.6, 0] },
  "rooms": [
    { "id": "r", "min": [-2, 0, -2], "max": [2, 3, 2] },
    { "id": "s", "min": [2, 0, -2], "max": [6, 3, 2] }
  ],
  "portals": [
    { "id": "east", "room": "r", "center": )" +
           center + R"(, "normal": )" + normal + R"(, "width": 1, "height": 2.2, "target": "west" },
    { "id": "west", "room": "s", "center": [2, 1.1, 0], "normal": [1, 0, 0], "width": 1, "height": 2.2,
      "target": "east" }
  ]
})";
}

TEST(LayoutDoorNormal, ADoorInAWallFacingOutIsALoudWarningAtItsNormal) {
    const LoadResult r = load(with_door("[2, 1.1, 0]", "[1, 0, 0]"));
    ASSERT_TRUE(r.errors.empty()) << all_messages(r.errors);
    ASSERT_EQ(r.warnings.size(), 1u) << all_messages(r.warnings);
    ASSERT_EQ(r.loud_warnings.size(), 1u);
    EXPECT_EQ(r.loud_warnings[0].str(), r.warnings[0].str());
    EXPECT_EQ(r.warnings[0].message,
              "portals[0].normal: door \"east\" lies in the +x face of room \"r\" but its normal points out of the "
              "room, so it makes no hole: it stands free, hidden in the face, and nobody can see or walk through it; "
              "flip the normal to [-1, 0, 0]");
    EXPECT_EQ(r.warnings[0].line, 9);
    EXPECT_EQ(r.layout->portals[0].hole_face, -1);  // still loads, as before
}

TEST(LayoutDoorNormal, ADoorFacingIntoItsRoomOrStandingFreeIsNoWarning) {
    for (const auto& [center, normal] :
         {std::pair{"[2, 1.1, 0]", "[-1, 0, 0]"}, std::pair{"[0, 1.1, 0]", "[1, 0, 0]"}}) {
        const LoadResult r = load(with_door(center, normal));
        ASSERT_TRUE(r.errors.empty()) << all_messages(r.errors);
        EXPECT_TRUE(r.warnings.empty()) << center << " " << normal << ": " << all_messages(r.warnings);
        EXPECT_TRUE(r.loud_warnings.empty());
    }
}

TEST(LayoutDoorNormal, APrismRoomsDoorFacingOutIsWarnedToo) {
    std::string text = with_door("[2, 1.1, 0]", "[1, 0, 0]");
    text = replace_once(text, R"("min": [-2, 0, -2], "max": [2, 3, 2])",
                        R"("floor": [[-2, -2], [2, -2], [2, 2], [-2, 2]], "y": [0, 3])");
    const LoadResult r = load(text);
    ASSERT_TRUE(r.errors.empty()) << all_messages(r.errors);
    ASSERT_EQ(r.loud_warnings.size(), 1u) << all_messages(r.warnings);
    EXPECT_NE(r.loud_warnings[0].message.find("flip the normal to [-1, 0, 0]"), std::string::npos);
}

// Every layout the project ships and tests with still loads, none with a
// door facing out.
TEST(LayoutDoorNormal, NoShippedLayoutHasADoorFacingOut) {
    namespace fs = std::filesystem;
    int loaded = 0;
    for (const std::string& dir : {std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts", kLayoutDir}) {
        for (const auto& entry : fs::directory_iterator(dir)) {
            if (entry.path().extension() != ".json") continue;
            const LoadResult r = load_layout_file(entry.path().string());
            if (!r.errors.empty()) continue;  // tests/data holds invalid layouts on purpose
            ++loaded;
            EXPECT_TRUE(r.loud_warnings.empty()) << entry.path() << ": " << all_messages(r.loud_warnings);
        }
    }
    EXPECT_GT(loaded, 20);
}

}  // namespace
}  // namespace layout_test
