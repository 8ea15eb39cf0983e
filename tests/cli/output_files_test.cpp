// CommandOutputs: an input declared after the outputs (a layout's textures
// and models, known once it is loaded) is checked like one declared before,
// and the message names the output first, with the file it would overwrite.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "cli/errors.hpp"
#include "cli/output_files.hpp"
#include "common/temp_dir.hpp"

namespace impossible::cli {
namespace {

std::string refusal(CommandOutputs& outputs, const std::string& what, const std::string& path) {
    try {
        outputs.input(what, path);
    } catch (const UsageError& e) {
        return e.what();
    }
    return "(accepted)";
}

TEST(CommandOutputs, AnInputDeclaredAfterAnOutputIsRefusedNamingTheOutput) {
    test::TempDir dir("command_outputs_late_input");
    std::ofstream(dir / "brick.png") << "texture";
    std::filesystem::create_hard_link(dir / "brick.png", dir / "hard.png");
    CommandOutputs outputs;
    outputs.output("--out", (dir / "x.png").string());
    outputs.output("--ids", (dir / "hard.png").string());
    EXPECT_EQ(refusal(outputs, "the texture", (dir / "other.png").string()), "(accepted)");
    EXPECT_EQ(refusal(outputs, "the texture", (dir / "brick.png").string()),
              "--ids " + (dir / "hard.png").string() + " is the same file as the texture " +
                  (dir / "brick.png").string() + "; it would be overwritten");
}

TEST(CommandOutputs, ReadingOneFileTwiceIsFine) {
    test::TempDir dir("command_outputs_twice");
    std::ofstream(dir / "a.png") << "a";
    CommandOutputs outputs;
    outputs.input("the texture", (dir / "a.png").string());
    EXPECT_EQ(refusal(outputs, "the glTF model", (dir / "a.png").string()), "(accepted)");
}

}  // namespace
}  // namespace impossible::cli
