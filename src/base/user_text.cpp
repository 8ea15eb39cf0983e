#include "base/user_text.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace impossible {

namespace {

// Length of the valid UTF-8 sequence at text[i], or 0 if it is not one.
std::size_t utf8_sequence_length(std::string_view text, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char b0 = byte(i);
    if (b0 < 0x80) return 1;
    std::size_t length = 0;
    unsigned min_code = 0;
    unsigned code = 0;
    if ((b0 & 0xE0) == 0xC0) {
        length = 2, min_code = 0x80, code = b0 & 0x1Fu;
    } else if ((b0 & 0xF0) == 0xE0) {
        length = 3, min_code = 0x800, code = b0 & 0x0Fu;
    } else if ((b0 & 0xF8) == 0xF0) {
        length = 4, min_code = 0x10000, code = b0 & 0x07u;
    } else {
        return 0;
    }
    if (i + length > text.size()) return 0;
    for (std::size_t k = 1; k < length; ++k) {
        if ((byte(i + k) & 0xC0) != 0x80) return 0;
        code = (code << 6) | (byte(i + k) & 0x3Fu);
    }
    if (code < min_code || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return 0;
    return length;
}

void append_hex_escape(std::string& out, unsigned char b) {
    static const char digits[] = "0123456789abcdef";
    out += "\\x";
    out += digits[b >> 4];
    out += digits[b & 0xF];
}

// Control bytes and bytes that are not valid UTF-8 become \xNN; with
// `quotes`, '"' and '\\' get a backslash too. Stops after `max_characters`
// characters (a UTF-8 sequence or a stray byte each) and returns the number
// of bytes of `text` it took.
std::size_t append_escaped(std::string& out, std::string_view text, bool quotes,
                           std::size_t max_characters = std::string_view::npos) {
    std::size_t i = 0;
    for (std::size_t written = 0; i < text.size() && written < max_characters; ++written) {
        const unsigned char b = static_cast<unsigned char>(text[i]);
        if (quotes && (b == '"' || b == '\\')) {
            out += '\\';
            out += static_cast<char>(b);
            ++i;
        } else if (b < 0x20 || b == 0x7F) {
            append_hex_escape(out, b);
            ++i;
        } else if (const std::size_t n = utf8_sequence_length(text, i); n > 0) {
            out.append(text.substr(i, n));
            i += n;
        } else {
            append_hex_escape(out, b);
            ++i;
        }
    }
    return i;
}

}  // namespace

std::string quote(std::string_view text, std::size_t max_characters) {
    std::string out = "\"";
    const std::size_t shown = append_escaped(out, text, true, max_characters);
    out += '"';
    if (shown < text.size()) out += "... (" + std::to_string(text.size() - shown) + " more bytes)";
    return out;
}

std::string printable(std::string_view text, std::size_t max_characters) {
    std::string out;
    const std::size_t shown = append_escaped(out, text, false, max_characters);
    if (shown < text.size()) out += "... (" + std::to_string(text.size() - shown) + " more bytes)";
    return out;
}

std::vector<TextPosition> text_positions(std::string_view text, const std::vector<std::size_t>& offsets) {
    std::vector<TextPosition> out;
    out.reserve(offsets.size());
    const bool has_bom = text.substr(0, 3) == "\xEF\xBB\xBF";
    int line = 1;
    int column = 1;
    std::size_t i = 0;
    for (std::size_t wanted : offsets) {
        if (wanted > text.size()) wanted = text.size();
        for (; i < wanted; ++i) {
            const auto b = static_cast<unsigned char>(text[i]);
            if (b == '\n') {
                ++line;
                column = 1;
            } else if ((b & 0xC0) != 0x80 && !(has_bom && i == 0)) {
                // A byte that starts a code point (continuation bytes don't
                // count, nor does the byte order mark: its bytes 1 and 2 are
                // continuation bytes).
                ++column;
            }
        }
        out.push_back({line, column});
    }
    return out;
}

TextPosition text_position(std::string_view text, std::size_t offset) { return text_positions(text, {offset}).front(); }

bool has_control_character(std::string_view text) {
    for (char c : text) {
        if (static_cast<unsigned char>(c) < 0x20) return true;
    }
    return false;
}

std::string count_of(std::size_t n, const char* singular, const char* plural) {
    return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

}  // namespace impossible
