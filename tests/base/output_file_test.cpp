// Output files (base/output_file.hpp) and one-line texts (base/text.hpp).
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "base/file_io.hpp"
#include "base/output_file.hpp"
#include "base/text.hpp"
#include "common/temp_dir.hpp"

namespace impossible {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

class OutputFile : public test::TempDirTest {};

TEST_F(OutputFile, WritesAllOrNothing) {
    std::ofstream(dir_ / "old.txt") << "old";
    const Result<void> failed =
        write_output_files({{(dir_ / "old.txt").string(), "new"}, {(dir_ / "missing/x.txt").string(), "x"}});
    ASSERT_FALSE(failed);
    EXPECT_NE(failed.error().find("missing/x.txt: cannot write: No such file or directory"), std::string::npos)
        << failed.error();
    EXPECT_EQ(slurp(dir_ / "old.txt"), "old");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_), {}), 1);  // no temporary file left

    ASSERT_TRUE(write_output_files({{(dir_ / "old.txt").string(), "new"}, {(dir_ / "b.txt").string(), "b"}}));
    EXPECT_EQ(slurp(dir_ / "old.txt"), "new");
    EXPECT_EQ(slurp(dir_ / "b.txt"), "b");
}

TEST_F(OutputFile, KeepsTheModeOfAReplacedFile) {
    std::ofstream(dir_ / "x.sh") << "old";
    fs::permissions(dir_ / "x.sh", fs::perms(0750));
    ASSERT_TRUE(write_output_file((dir_ / "x.sh").string(), "new"));
    struct stat st {};
    ASSERT_EQ(::stat((dir_ / "x.sh").c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0750u);
}

TEST_F(OutputFile, WritesThroughALinkAndKeepsIt) {
    fs::create_symlink("target.txt", dir_ / "link.txt");
    ASSERT_TRUE(write_output_file((dir_ / "link.txt").string(), "through"));
    EXPECT_TRUE(fs::is_symlink(dir_ / "link.txt"));
    EXPECT_EQ(slurp(dir_ / "target.txt"), "through");
    EXPECT_EQ(identify_file((dir_ / "link.txt").string()), identify_file((dir_ / "target.txt").string()));
}

TEST_F(OutputFile, IdentifiesFilesStillToBeMadeByTheirNormalPath) {
    EXPECT_EQ(identify_file((dir_ / "a/../new.png").string()), identify_file((dir_ / "new.png").string()));
    EXPECT_FALSE(identify_file((dir_ / "new.png").string()) == identify_file((dir_ / "other.png").string()));
    EXPECT_TRUE(identify_file("/dev/null").shareable);
}

TEST_F(OutputFile, ADirectoryIsAnError) {
    const Result<void> r = write_output_file(dir_.string(), "x");
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().find("is a directory"), std::string::npos);
}

TEST(FileIo, EndlessDevicesStopAtTheLimit) {
    const Result<std::vector<unsigned char>> zero = read_file_bytes("/dev/zero", 1000, false);
    ASSERT_FALSE(zero);
    EXPECT_EQ(zero.error(), "is too large (more than 1000 bytes; the limit is 1000 bytes)");
    EXPECT_EQ(read_file_bytes("/dev/zero", 1000, true).error(), "is not a regular file");
}

TEST(OneLine, EscapesControlCharactersAndCuts) {
    EXPECT_EQ(one_line("a\nb\tc\x01"), "a\\nb\\tc\\x01");
    EXPECT_EQ(one_line(std::string(10, 'x'), 4), "xxxx... (6 more bytes)");
    // Never in the middle of a character: "é" is two bytes.
    EXPECT_EQ(one_line("ab\xC3\xA9z", 3), "ab... (3 more bytes)");
    EXPECT_EQ(one_line("plain"), "plain");
}

}  // namespace
}  // namespace impossible
