// Text from a user's files in diagnostics: quoted strings, bytes that are not
// text, counts of things, and line/column positions.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include <string_view>
#include <vector>

namespace impossible {

// Diagnostics quote at most this many characters of a user's string, and of
// a file's path (which a user wants whole; the system's own limit is 4096).
inline constexpr std::size_t kQuotedCharacters = 100;
inline constexpr std::size_t kQuotedPathCharacters = 4096;

// A string as a JSON string literal (quotes, escapes), safe to print. Past
// kQuotedCharacters characters it is cut, and says so: "abc"... (N more
// bytes), so that a megabyte key still makes a short one-line message.
std::string quote(std::string_view text, std::size_t max_characters = kQuotedCharacters);

// Text with bytes that are not valid UTF-8, and control characters, written as
// \xNN, so that a message never carries raw binary. With `max_characters`
// it is cut like quote().
std::string printable(std::string_view text, std::size_t max_characters = std::string_view::npos);

// "1 texture", "3 textures".
std::string count_of(std::size_t n, const char* singular, const char* plural);

// Whether the text holds a byte below 0x20 (a path that does: an error).
bool has_control_character(std::string_view text);

struct TextPosition {
    int line = 0;    // 1-based
    int column = 0;  // 1-based, counted in Unicode code points
};

// Line and column of a byte offset (clamped to the text's end). A UTF-8 byte
// order mark at the start does not count as a column.
TextPosition text_position(std::string_view text, std::size_t offset);

// The same for many offsets at once, in one pass over the text: `offsets`
// must be sorted ascending.
std::vector<TextPosition> text_positions(std::string_view text, const std::vector<std::size_t>& offsets);

}  // namespace impossible
