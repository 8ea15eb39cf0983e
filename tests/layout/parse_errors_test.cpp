// Text that is not a layout at all: malformed JSON, truncated, empty, binary,
// too deep or too large, missing files, directories. Each gives one clean
// error with a position where one exists.
#include <filesystem>
#include <fstream>

#include "layout_test_util.hpp"

namespace layout_test {
namespace {

// Line and column just past the end of the text.
Pos end_of(const std::string& text) {
    Pos p{1, 1};
    for (const char c : text) {
        if (c == '\n') {
            ++p.line;
            p.column = 1;
        } else if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) {
            ++p.column;
        }
    }
    return p;
}

void expect_clean_message(const Diagnostic& d) {
    EXPECT_EQ(d.message.find("json.exception"), std::string::npos) << d.message;
    for (const char c : d.message) {
        const auto b = static_cast<unsigned char>(c);
        EXPECT_TRUE(b >= 0x20 && b < 0x7F) << "raw byte " << int(b) << " in " << d.message;
    }
}

void expect_json_error(const std::string& text, Pos at, const std::string& message_start) {
    const LoadResult r = load(text);
    EXPECT_FALSE(r.layout.has_value());
    ASSERT_EQ(r.errors.size(), 1u) << all_messages(r.errors);
    EXPECT_EQ(r.errors[0].line, at.line) << r.errors[0].str();
    EXPECT_EQ(r.errors[0].column, at.column) << r.errors[0].str();
    EXPECT_EQ(r.errors[0].message.substr(0, message_start.size()), message_start) << r.errors[0].str();
    expect_clean_message(r.errors[0]);
}

TEST(LayoutParseErrors, MalformedJsonPointsAtTheBadToken) {
    const std::string text = "{\n  \"format\": \"impossible-layout\",,\n  \"version\": 1\n}\n";
    expect_json_error(text, {2, 33}, "invalid JSON: syntax error while parsing object key");
    expect_json_error("{\"a\": tru}", {1, 7}, "invalid JSON: syntax error while parsing value - invalid literal");
    expect_json_error("{\"a\": 1 \"b\": 2}", {1, 9}, "invalid JSON: syntax error while parsing object");
    expect_json_error("{\"a\": [1, 2,]}", {1, 13}, "invalid JSON: syntax error while parsing value");
}

TEST(LayoutParseErrors, TruncatedFilesPointAtTheEnd) {
    const std::string whole = two_rooms();
    for (const std::size_t length :
         {std::size_t{1}, std::size_t{57}, std::size_t{200}, whole.size() / 2, whole.size() - 3}) {
        const std::string text = whole.substr(0, length);
        SCOPED_TRACE(length);
        expect_json_error(text, end_of(text), "invalid JSON: ");
    }
}

TEST(LayoutParseErrors, EmptyFilesSaySo) {
    expect_json_error("", {1, 1}, "the file is empty");
    expect_json_error(" \n\t\r\n", {1, 1}, "the file is empty");
    expect_json_error("\xEF\xBB\xBF", {1, 1}, "the file is empty");
}

TEST(LayoutParseErrors, InvalidUtf8IsAnErrorAtTheByte) {
    expect_json_error("{\"name\": \"a\xFF\"}", {1, 12}, "invalid JSON: ");
    expect_json_error("{\"name\": \"\xC3\"}", {1, 11}, "invalid JSON: ");  // cut sequence
    expect_json_error("{\"na\xE9me\": 1}", {1, 5}, "invalid JSON: ");      // Latin-1 in a key
    expect_json_error("\xFF\xFE{}", {1, 1}, "invalid JSON: ");             // UTF-16 BOM
}

TEST(LayoutParseErrors, ColumnsCountCharactersNotBytes) {
    // "é" and "→" take 2 and 3 bytes but one column each.
    const std::string text =
        "{\"format\": \"impossible-layout\", \"name\": \"café → x\", \"version\": 7,\n"
        "\"start\": {}, \"rooms\": []}";
    const LoadResult r = load(text);
    EXPECT_TRUE(has_error(r, {1, 64}, "version: unsupported version 7")) << all_messages(r.errors);
}

TEST(LayoutParseErrors, ControlCharactersAndBadEscapes) {
    expect_json_error("{\"name\": \"a\tb\"}", {1, 12}, "invalid JSON: ");
    expect_json_error("{\"name\": \"a\\qb\"}", {1, 13}, "invalid JSON: ");
    expect_json_error(std::string("{\"name\"\0: 1}", 12), {1, 8}, "a NUL byte (\\x00): a layout is JSON text");
    expect_json_error("{\"name\": \"\\ud800\"}", {1, 17}, "invalid JSON: ");  // lone surrogate, noticed at its end
}

TEST(LayoutParseErrors, NumbersTooLargeForADouble) {
    expect_json_error("{\"version\": 1e400}", {1, 13}, "invalid JSON: number overflow");
    expect_json_error("{\"a\": [0, -1e999999]}", {1, 11}, "invalid JSON: number overflow");
}

TEST(LayoutParseErrors, CommentsAndTrailingTextAreNotJson) {
    expect_json_error("// a layout\n{}", {1, 1}, "invalid JSON: ");
    const std::string trailing = two_rooms() + "x";
    expect_json_error(trailing, end_of(two_rooms()), "invalid JSON: syntax error while parsing value");
    expect_json_error("{} {}", {1, 4}, "invalid JSON: ");
}

TEST(LayoutParseErrors, DeepNestingIsRefused) {
    const std::string text = "{\"rooms\": " + std::string(100000, '[') + std::string(100000, ']') + "}";
    // The object is level 1; the 64th "[" is level 65.
    expect_json_error(text, {1, 11 + 63}, "the JSON is nested deeper than 64 levels");
    // 63 levels inside the object are fine as JSON (and then simply a wrong layout).
    const std::string ok = "{\"_deep\": " + std::string(63, '[') + std::string(63, ']') + "}";
    const LoadResult r = load(ok);
    ASSERT_FALSE(r.errors.empty());
    EXPECT_EQ(r.errors[0].message, "missing required field \"format\"");
}

TEST(LayoutParseErrors, HugeArraysAreRefused) {
    std::string text = "[";
    for (int i = 0; i < 200000; ++i) text += "0,";
    text += "0]";
    // The array is value 1; its element i is value i + 2; value 200001 passes the limit.
    expect_json_error(text, {1, 2 + 2 * 199999}, "the JSON holds more than 200000 values");
}

TEST(LayoutParseErrors, RepeatedKeysAreErrorsAtTheSecondKey) {
    const std::string text = replace_once(two_rooms(), "\"version\": 1,", "\"version\": 1, \"version\": 1,");
    expect_one_error(text, "\"version\"", "version: repeated field", 1);
    const std::string nested = replace_once(two_rooms(), "\"checker\": 0.5,", "\"checker\": 0.5, \"checker\": 0.25,");
    expect_one_error(nested, "\"checker\"", "rooms[0].checker: repeated field", 1);
}

TEST(LayoutParseErrors, AByteOrderMarkIsSkipped) {
    expect_valid("\xEF\xBB\xBF" + two_rooms());
    const LoadResult r = load("\xEF\xBB\xBF{\"format\": 5}");
    EXPECT_TRUE(has_error(r, {1, 12}, "format: must be a string (got a number)")) << all_messages(r.errors);
}

TEST(LayoutParseErrors, MissingFilesAndDirectories) {
    const std::string missing = kLayoutDir + "/no_such_layout.json";
    const LoadResult a = load_layout_file(missing);
    ASSERT_EQ(a.errors.size(), 1u);
    EXPECT_EQ(a.errors[0].str(), missing + ": the file does not exist");
    EXPECT_FALSE(a.layout.has_value());

    const LoadResult b = load_layout_file(kLayoutDir);
    ASSERT_EQ(b.errors.size(), 1u);
    EXPECT_EQ(b.errors[0].str(), kLayoutDir + ": the file is a directory");

    const LoadResult c = load_layout_file("");
    ASSERT_EQ(c.errors.size(), 1u);
    EXPECT_EQ(c.errors[0].message, "the file has an empty path");
}

TEST(LayoutParseErrors, TooLargeFilesAreRefusedBeforeParsing) {
    const std::string big(5u << 20, ' ');
    const LoadResult r = load(big);
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].str(), "t.json: the file is too large (5 MiB; the limit is 4 MiB)");

    const std::string path = temp_path("big_layout.json");
    {
        std::ofstream out(path, std::ios::binary);
        out << big;
    }
    const LoadResult f = load_layout_file(path);
    ASSERT_EQ(f.errors.size(), 1u);
    EXPECT_EQ(f.errors[0].str(), path + ": the file is too large (5 MiB; the limit is 4 MiB)");
    std::filesystem::remove(path);
}

}  // namespace
}  // namespace layout_test
