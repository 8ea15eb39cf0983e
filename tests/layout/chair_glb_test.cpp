// layouts/models/chair.glb is exactly what tools/make_glb writes, so the
// model in the tree can always be regenerated from source.
#include <cstdlib>
#include <filesystem>

#include "layout_test_util.hpp"

namespace layout_test {
namespace {

namespace fs = std::filesystem;

TEST(ChairGlb, RegeneratingGivesIdenticalBytes) {
    const std::string out = temp_path("chair_regenerated.glb");
    fs::remove(out);
    ASSERT_EQ(run("'" + std::string(IMPOSSIBLE_MAKE_GLB) + "' '" + out + "'"), 0);
    const std::string fresh = read_text(out);
    const std::string kept = read_text(kChairGlb);
    EXPECT_GT(kept.size(), 1000u);
    EXPECT_TRUE(fresh == kept) << "regenerate it: make_glb layouts/models/chair.glb";
    // A second run writes the same bytes again.
    ASSERT_EQ(run("'" + std::string(IMPOSSIBLE_MAKE_GLB) + "' '" + out + "'"), 0);
    EXPECT_TRUE(read_text(out) == fresh);
    fs::remove(out);
}

TEST(ChairGlb, IsAWellFormedBinaryGltf) {
    const std::string glb = read_text(kChairGlb);
    ASSERT_GE(glb.size(), 28u);
    const auto u32 = [&](std::size_t at) {
        return std::uint32_t(std::uint8_t(glb[at])) | std::uint32_t(std::uint8_t(glb[at + 1])) << 8 |
               std::uint32_t(std::uint8_t(glb[at + 2])) << 16 | std::uint32_t(std::uint8_t(glb[at + 3])) << 24;
    };
    EXPECT_EQ(glb.substr(0, 4), "glTF");
    EXPECT_EQ(u32(4), 2u);          // version
    EXPECT_EQ(u32(8), glb.size());  // total length
    const std::uint32_t json_length = u32(12);
    EXPECT_EQ(u32(16), 0x4E4F534Au);  // "JSON"
    EXPECT_EQ(json_length % 4, 0u);
    const std::size_t bin_at = 20 + json_length;
    ASSERT_LE(bin_at + 8, glb.size());
    EXPECT_EQ(u32(bin_at + 4), 0x004E4942u);  // "BIN\0"
    EXPECT_EQ(bin_at + 8 + u32(bin_at), glb.size());
}

TEST(ChairGlb, UsageErrors) {
    EXPECT_NE(run("'" + std::string(IMPOSSIBLE_MAKE_GLB) + "' 2>/dev/null"), 0);
    EXPECT_NE(run("'" + std::string(IMPOSSIBLE_MAKE_GLB) + "' /no/such/dir/chair.glb 2>/dev/null"), 0);
}

}  // namespace
}  // namespace layout_test
