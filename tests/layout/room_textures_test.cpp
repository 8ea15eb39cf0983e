// Room textures: `textures` (per face and `all`) and `texture_size`, the
// images read relative to the layout, shared between faces and rooms, and
// the messages for what is wrong, each at its field.
#include <filesystem>
#include <fstream>

#include "hostile/png_bytes.hpp"
#include "layout_test_util.hpp"

namespace layout_test {
namespace {

namespace fs = std::filesystem;

// A w x h RGBA PNG of one colour.
std::string png(std::uint32_t w, std::uint32_t h, unsigned char r, unsigned char g, unsigned char b) {
    std::string rows;
    for (std::uint32_t y = 0; y < h; ++y) {
        rows += '\0';
        for (std::uint32_t x = 0; x < w; ++x) rows += std::string{char(r), char(g), char(b), char(255)};
    }
    return impossible::hostile::png_file(w, h, 8, 6, rows);
}

class RoomTextures : public ::testing::Test {
protected:
    fs::path dir;

    void SetUp() override {
        dir =
            temp_path("room_textures_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir);
        fs::create_directories(dir / "tex");
        write("tex/red.png", png(2, 2, 255, 0, 0));
        write("tex/blue.png", png(1, 3, 0, 0, 255));
    }
    void TearDown() override { fs::remove_all(dir); }

    void write(const std::string& name, const std::string& bytes) const {
        std::ofstream(dir / name, std::ios::binary) << bytes;
    }
    LoadResult load_here(const std::string& text) const { return load_layout_text(text, "t.json", dir.string()); }

    // two_rooms.json with `fields` added to the hall (rooms[0]).
    static std::string hall_with(const std::string& fields) {
        return replace_once(two_rooms(), "\"checker\": 0.5,", "\"checker\": 0.5, " + fields + ",");
    }

    Layout expect_valid_here(const std::string& text) const {
        LoadResult r = load_here(text);
        EXPECT_TRUE(r.errors.empty()) << all_messages(r.errors);
        return r.layout ? *r.layout : Layout{};
    }
    // Exactly one error, at the first `needle`, starting with `message_start`.
    void expect_one_error_here(const std::string& text, const std::string& needle,
                               const std::string& message_start) const {
        const LoadResult r = load_here(text);
        EXPECT_FALSE(r.layout.has_value());
        ASSERT_EQ(r.errors.size(), 1u) << all_messages(r.errors);
        const Pos want = position_of(text, needle);
        EXPECT_EQ(r.errors[0].line, want.line) << r.errors[0].str();
        EXPECT_EQ(r.errors[0].column, want.column) << r.errors[0].str();
        EXPECT_EQ(r.errors[0].message.substr(0, message_start.size()), message_start) << r.errors[0].str();
    }
};

TEST_F(RoomTextures, AFacesOwnKeyWinsOverAll) {
    const Layout layout =
        expect_valid_here(hall_with(R"("textures": { "all": "tex/red.png", "floor": "tex/blue.png" })"));
    ASSERT_EQ(layout.rooms.size(), 2u);
    const Room& hall = layout.rooms[0];
    ASSERT_NE(hall.face_texture[int(Face::Floor)], nullptr);
    EXPECT_EQ(hall.face_texture[int(Face::Floor)]->width, 1);
    EXPECT_EQ(hall.face_texture[int(Face::Floor)]->height, 3);
    const std::vector<std::uint8_t> blue = {0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255, 255};
    EXPECT_EQ(hall.face_texture[int(Face::Floor)]->data, blue);
    for (Face f : {Face::Ceiling, Face::NegX, Face::PosX, Face::NegZ, Face::PosZ}) {
        ASSERT_NE(hall.face_texture[int(f)], nullptr);
        EXPECT_EQ(hall.face_texture[int(f)], hall.face_texture[int(Face::Ceiling)]) << "one image, shared";
        EXPECT_EQ(hall.face_texture[int(f)]->width, 2);
    }
    const std::vector<std::uint8_t> red = {255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255};
    EXPECT_EQ(hall.face_texture[int(Face::NegX)]->data, red);
    EXPECT_EQ(hall.texture_size, 1.0);
    for (const auto& texture : layout.rooms[1].face_texture) EXPECT_EQ(texture, nullptr);
    const std::string summary = summary_text(layout, summarize(layout));
    EXPECT_NE(summary.find("textures: 2 images, 6 textured room faces\n"), std::string::npos) << summary;
}

TEST_F(RoomTextures, OnlyTheFacesNamedGetATexture) {
    const Layout layout = expect_valid_here(hall_with(R"("textures": { "-z": "tex/red.png" }, "texture_size": 0.5)"));
    const Room& hall = layout.rooms[0];
    for (int f = 0; f < kFaceCount; ++f) {
        EXPECT_EQ(hall.face_texture[std::size_t(f)] != nullptr, f == int(Face::NegZ)) << kFaceNames[std::size_t(f)];
    }
    EXPECT_EQ(hall.texture_size, 0.5);
}

TEST_F(RoomTextures, OnePathIsReadOncePerLayout) {
    std::string text = hall_with(R"("textures": { "all": "tex/red.png" })");
    text = replace_once(text, "\"max\": [5, 2.6, 1.5] }",
                        "\"max\": [5, 2.6, 1.5], \"textures\": { \"+x\": \"./tex/../tex/red.png\" } }");
    const Layout layout = expect_valid_here(text);
    ASSERT_NE(layout.rooms[1].face_texture[int(Face::PosX)], nullptr);
    EXPECT_EQ(layout.rooms[1].face_texture[int(Face::PosX)], layout.rooms[0].face_texture[int(Face::Floor)]);
    const std::string summary = summary_text(layout, summarize(layout));
    EXPECT_NE(summary.find("textures: 1 image, 7 textured room faces\n"), std::string::npos) << summary;
}

TEST_F(RoomTextures, WithoutTexturesTheSummaryHasNoTextureLine) {
    const Layout layout = expect_valid_here(two_rooms());
    EXPECT_EQ(summary_text(layout, summarize(layout)).find("textures"), std::string::npos);
}

TEST_F(RoomTextures, UnknownKeysAndWrongTypesAreErrorsAtTheField) {
    expect_one_error_here(hall_with(R"("textures": { "wall": "tex/red.png" })"), "\"wall\"",
                          "rooms[0].textures.wall: unknown face \"wall\" (textures are named by \"floor\", "
                          "\"ceiling\", \"-x\", \"+x\", \"-z\", \"+z\" and \"all\")");
    expect_one_error_here(hall_with(R"("textures": { "floor": 7 })"), "7 }",
                          "rooms[0].textures.floor: must be a string (got a number)");
    expect_one_error_here(hall_with(R"("textures": ["tex/red.png"])"), "[\"tex",
                          "rooms[0].textures: must be an object (got an array)");
    expect_one_error_here(hall_with(R"("textures": { "floor": "" })"), "\"\" }",
                          "rooms[0].textures.floor: must name a PNG or JPEG file (got an empty path)");
    // A comment key is allowed, as in face_colors.
    expect_valid_here(hall_with(R"("textures": { "_note": 5 })"));
}

TEST_F(RoomTextures, TextureSizeIsALengthAboveZero) {
    expect_one_error_here(hall_with(R"("texture_size": 0e0)"), "0e0", "rooms[0].texture_size: ");
    expect_one_error_here(hall_with(R"("texture_size": -0.25)"), "-0.25", "rooms[0].texture_size: ");
    expect_one_error_here(hall_with(R"("texture_size": "big")"), "\"big\"",
                          "rooms[0].texture_size: must be a number (got a string)");
    expect_one_error_here(hall_with(R"("texture_size": 1e9)"), "1e9", "rooms[0].texture_size: ");
}

TEST_F(RoomTextures, FilesThatAreMissingNotImagesOrTooLargeAreErrorsAtThePath) {
    const std::string resolved = (dir / "tex/none.png").string();
    expect_one_error_here(hall_with(R"("textures": { "floor": "tex/none.png" })"), "\"tex/none.png\"",
                          "rooms[0].textures.floor: the image \"" + resolved + "\" does not exist");
    write("tex/text.png", "hello");
    expect_one_error_here(hall_with(R"("textures": { "ceiling": "tex/text.png" })"), "\"tex/text.png\"",
                          "rooms[0].textures.ceiling: the image \"" + (dir / "tex/text.png").string() +
                              "\" is neither PNG nor JPEG data");
    std::string cut = png(2, 2, 1, 2, 3);
    cut.resize(cut.size() - 30);
    write("tex/cut.png", cut);
    expect_one_error_here(hall_with(R"("textures": { "all": "tex/cut.png" })"), "\"tex/cut.png\"",
                          "rooms[0].textures.all: the image \"" + (dir / "tex/cut.png").string() +
                              "\" could not be decoded as PNG: it is truncated");
    write("tex/wide.png", png(9000, 1, 0, 0, 0));
    expect_one_error_here(hall_with(R"("textures": { "+z": "tex/wide.png" })"), "\"tex/wide.png\"",
                          "rooms[0].textures.+z: the image \"" + (dir / "tex/wide.png").string() +
                              "\" is 9000 x 1 pixels; the limit is 8192 pixels on a side");
    write("tex/empty.png", "");
    expect_one_error_here(hall_with(R"("textures": { "-x": "tex/empty.png" })"), "\"tex/empty.png\"",
                          "rooms[0].textures.-x: the image \"" + (dir / "tex/empty.png").string() + "\" is empty");
    fs::create_directories(dir / "tex/folder.png");
    expect_one_error_here(
        hall_with(R"("textures": { "-x": "tex/folder.png" })"), "\"tex/folder.png\"",
        "rooms[0].textures.-x: the image \"" + (dir / "tex/folder.png").string() + "\" is a directory");
}

TEST_F(RoomTextures, ABrokenImageSharedByTwoRoomsIsReportedAtBoth) {
    std::string text = hall_with(R"("textures": { "all": "tex/none.png" })");
    text = replace_once(text, "\"max\": [5, 2.6, 1.5] }",
                        "\"max\": [5, 2.6, 1.5], \"textures\": { \"all\": \"tex/none.png\" } }");
    const LoadResult r = load_here(text);
    ASSERT_EQ(r.errors.size(), 2u) << all_messages(r.errors);
    EXPECT_EQ(r.errors[0].message.substr(0, 23), "rooms[0].textures.all: ");
    EXPECT_EQ(r.errors[1].message.substr(0, 23), "rooms[1].textures.all: ");
}

}  // namespace
}  // namespace layout_test
