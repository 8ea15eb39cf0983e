// What every fuzzer asks of an error message: one line of text that is safe
// on a terminal, as the program prints it (README: bad input prints one line;
// base/user_text.hpp: "a message never carries raw binary"). So: not empty,
// no byte below 0x20 (a newline, an escape) and no DEL, valid UTF-8.
#pragma once

#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace impossible::fuzz {

inline bool is_clean_line(std::string_view text) {
    if (text.empty()) return false;
    std::size_t i = 0;
    while (i < text.size()) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c < 0x20 || c == 0x7F) return false;
        if (c < 0x80) {
            ++i;
            continue;
        }
        // A UTF-8 sequence: its length from the lead byte, no overlong
        // forms, no surrogates, nothing above U+10FFFF.
        std::size_t length = 0;
        unsigned min = 0;
        unsigned code = 0;
        if (c >= 0xC2 && c <= 0xDF)
            length = 2, min = 0x80, code = c & 0x1F;
        else if (c >= 0xE0 && c <= 0xEF)
            length = 3, min = 0x800, code = c & 0x0F;
        else if (c >= 0xF0 && c <= 0xF4)
            length = 4, min = 0x10000, code = c & 0x07;
        else
            return false;
        if (i + length > text.size()) return false;
        for (std::size_t k = 1; k < length; ++k) {
            const auto b = static_cast<unsigned char>(text[i + k]);
            if ((b & 0xC0) != 0x80) return false;
            code = code << 6 | (b & 0x3F);
        }
        if (code < min || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return false;
        i += length;
    }
    return true;
}

// Ends the run (a finding): says which check failed, then aborts, so that
// libFuzzer keeps the input and prints the stack.
[[noreturn]] inline void fail(const char* what) {
    std::fprintf(stderr, "fuzz check failed: %s\n", what);
    std::abort();
}

// Ends the run unless `ok`; `what` names the check in the report.
inline void require(bool ok, const char* what) {
    if (!ok) fail(what);
}

// Ends the run unless `message` is one clean line; the report shows the
// message with every byte outside printable ASCII as \xNN.
inline void require_clean_line(std::string_view message) {
    if (is_clean_line(message)) return;
    std::fprintf(stderr, "fuzz check failed: an error message that is not one clean line: \"");
    for (const char ch : message) {
        const auto c = static_cast<unsigned char>(ch);
        if (c >= 0x20 && c < 0x7F && c != '\\')
            std::fputc(c, stderr);
        else
            std::fprintf(stderr, "\\x%02X", c);
    }
    std::fprintf(stderr, "\"\n");
    std::abort();
}

}  // namespace impossible::fuzz
