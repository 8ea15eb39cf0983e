// Text from a user's files in diagnostics: quoted strings, bytes that are not
// text, counts of things, and line/column positions.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include <string_view>
#include <vector>

namespace impossible {

// A string as a JSON string literal (quotes, escapes), safe to print.
std::string quote(std::string_view text);

// Text with bytes that are not valid UTF-8, and control characters, written as
// \xNN, so that a message never carries raw binary.
std::string printable(std::string_view text);

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
