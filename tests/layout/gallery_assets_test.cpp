// layouts/gallery/ holds exactly what tools/make_gallery_assets writes, so
// the textures and models of gallery.json can always be regenerated from
// source; and gallery.json uses each of them.
#include <cstdlib>
#include <filesystem>
#include <set>

#include "common/temp_dir.hpp"
#include "layout_test_util.hpp"

namespace layout_test {
namespace {

namespace fs = std::filesystem;

const std::string kGalleryDir = std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/gallery";

std::string make_assets(const fs::path& dir) {
    return "'" + std::string(IMPOSSIBLE_MAKE_GALLERY_ASSETS) + "' '" + dir.string() + "'";
}

std::set<std::string> names_in(const fs::path& dir) {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename().string());
    return names;
}

TEST(GalleryAssets, RegeneratingGivesIdenticalFiles) {
    impossible::test::TempDir out("gallery_assets");
    ASSERT_EQ(run(make_assets(out.path())), 0);
    const std::set<std::string> made = names_in(out.path());
    EXPECT_EQ(made.size(), 8u);
    EXPECT_EQ(made, names_in(kGalleryDir)) << "layouts/gallery/ holds a file the tool does not write, or lacks one";
    for (const std::string& name : made) {
        const std::string kept = read_text(kGalleryDir + "/" + name);
        EXPECT_GT(kept.size(), 1000u) << name;
        EXPECT_TRUE(read_text((out / name).string()) == kept)
            << name << " differs; regenerate: make_gallery_assets layouts/gallery";
    }
    // A second run writes the same bytes again.
    impossible::test::TempDir again("gallery_assets_again");
    ASSERT_EQ(run(make_assets(again.path())), 0);
    for (const std::string& name : made) {
        EXPECT_TRUE(read_text((again / name).string()) == read_text((out / name).string())) << name;
    }
}

TEST(GalleryAssets, TheLayoutUsesEveryFile) {
    const std::string layout = read_text(std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/gallery.json");
    for (const std::string& name : names_in(kGalleryDir)) {
        EXPECT_NE(layout.find("\"gallery/" + name + "\""), std::string::npos) << name;
    }
}

TEST(GalleryAssets, UsageErrors) {
    EXPECT_NE(run("'" + std::string(IMPOSSIBLE_MAKE_GALLERY_ASSETS) + "' 2>/dev/null"), 0);
    EXPECT_NE(run(make_assets("/no/such/dir") + " 2>/dev/null"), 0);
}

}  // namespace
}  // namespace layout_test
