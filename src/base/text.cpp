#include "base/text.hpp"

namespace impossible {

std::string one_line(std::string_view text, std::size_t max_bytes) {
    std::string out;
    std::size_t i = 0;
    for (; i < text.size() && out.size() < max_bytes; ++i) {
        const auto b = static_cast<unsigned char>(text[i]);
        if (b == '\n')
            out += "\\n";
        else if (b == '\r')
            out += "\\r";
        else if (b == '\t')
            out += "\\t";
        else if (b < 0x20 || b == 0x7F) {
            static const char digits[] = "0123456789abcdef";
            out += "\\x";
            out += digits[b >> 4];
            out += digits[b & 0xF];
        } else {
            out += static_cast<char>(b);
        }
    }
    // Never end inside a UTF-8 sequence: drop a partial one.
    while (i < text.size() && (static_cast<unsigned char>(text[i]) & 0xC0) == 0x80 && !out.empty()) {
        out.pop_back();
        --i;
    }
    if (i < text.size()) out += "... (" + std::to_string(text.size() - i) + " more bytes)";
    return out;
}

}  // namespace impossible
