// Helpers for the layout tests: loading inline JSON, and finding the line
// and column a diagnostic must point at by searching the text.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "common/temp_dir.hpp"
#include "layout/layout.hpp"

namespace layout_test {

using namespace impossible::layout;
using namespace impossible::assets;  // the model types a glTF prop holds

inline const std::string kLayoutDir = std::string(IMPOSSIBLE_TEST_DATA) + "/layouts";
inline const std::string kChairGlb = std::string(IMPOSSIBLE_SOURCE_DIR) + "/layouts/models/chair.glb";

// A path in the temporary directory, unique to this process.
inline std::string temp_path(const std::string& name) { return impossible::test::temp_path(name).string(); }

inline std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Loads JSON text as "t.json" living in tests/data/layouts.
inline LoadResult load(const std::string& text) { return load_layout_text(text, "t.json", kLayoutDir); }

inline std::string all_messages(const std::vector<Diagnostic>& list) {
    std::string out;
    for (const Diagnostic& d : list) out += d.str() + "\n";
    return out;
}

inline std::string two_rooms() { return read_text(kLayoutDir + "/two_rooms.json"); }

// The text with the first `from` replaced by `to` (a test failure if absent).
inline std::string replace_once(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    if (at == std::string::npos) {
        ADD_FAILURE() << "test text has no " << from;
        return text;
    }
    return text.replace(at, from.size(), to);
}

inline std::string replace_all(std::string text, const std::string& from, const std::string& to) {
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
        text.replace(at, from.size(), to);
    }
    return text;
}

struct Pos {
    int line = 0;
    int column = 0;
};

// 1-based line and column (in code points) of the nth occurrence of needle.
inline Pos position_of(const std::string& text, const std::string& needle, int nth = 0) {
    std::size_t at = text.find(needle);
    for (int i = 0; i < nth && at != std::string::npos; ++i) at = text.find(needle, at + 1);
    if (at == std::string::npos) {
        ADD_FAILURE() << "test text has no " << needle;
        return {};
    }
    Pos p{1, 1};
    for (std::size_t i = 0; i < at; ++i) {
        const auto b = static_cast<unsigned char>(text[i]);
        if (b == '\n') {
            ++p.line;
            p.column = 1;
        } else if ((b & 0xC0) != 0x80) {
            ++p.column;
        }
    }
    return p;
}

// Whether an error sits at `pos` and its message starts with `message_start`.
inline bool has_error(const LoadResult& r, Pos pos, const std::string& message_start) {
    for (const Diagnostic& d : r.errors) {
        if (d.line == pos.line && d.column == pos.column &&
            d.message.compare(0, message_start.size(), message_start) == 0) {
            return true;
        }
    }
    return false;
}

// Loads `text` and expects exactly one error: at the first `needle` in the
// text, with a message starting with `message_start` (which names the field).
inline void expect_one_error(const std::string& text, const std::string& needle, const std::string& message_start,
                             int nth = 0) {
    const LoadResult r = load(text);
    EXPECT_FALSE(r.layout.has_value());
    ASSERT_EQ(r.errors.size(), 1u) << all_messages(r.errors);
    const Pos want = position_of(text, needle, nth);
    EXPECT_EQ(r.errors[0].line, want.line) << r.errors[0].str();
    EXPECT_EQ(r.errors[0].column, want.column) << r.errors[0].str();
    EXPECT_EQ(r.errors[0].message.substr(0, message_start.size()), message_start) << r.errors[0].str();
    EXPECT_EQ(r.errors[0].file, "t.json");
}

// Loads `text` and expects, among its errors, one at the nth `needle` with a
// message starting with `message_start`.
inline void expect_error(const std::string& text, const std::string& needle, const std::string& message_start,
                         int nth = 0) {
    const LoadResult r = load(text);
    EXPECT_FALSE(r.layout.has_value());
    EXPECT_TRUE(has_error(r, position_of(text, needle, nth), message_start))
        << "wanted " << message_start << " at " << position_of(text, needle, nth).line << ":"
        << position_of(text, needle, nth).column << "; got\n"
        << all_messages(r.errors);
}

// Loads `text` and expects no errors.
inline Layout expect_valid(const std::string& text) {
    LoadResult r = load(text);
    EXPECT_TRUE(r.errors.empty()) << all_messages(r.errors);
    EXPECT_TRUE(r.layout.has_value());
    return r.layout ? *r.layout : Layout{};
}

// Runs a shell command; its exit status as std::system gives it.
inline int run(const std::string& command) { return std::system(command.c_str()); }

}  // namespace layout_test
