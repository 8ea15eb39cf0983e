#include "base/number_text.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace impossible {

namespace {

// "0x…" or "0X…" after an optional sign.
bool hexadecimal(std::string_view text) {
    if (!text.empty() && (text[0] == '-' || text[0] == '+')) text.remove_prefix(1);
    return text.size() > 1 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X');
}

#if !defined(__EMSCRIPTEN__)
// Whether a number too large or too small for a double is the small kind:
// a negative exponent, or none and only zeros before the point.
bool underflows(std::string_view text) {
    const std::size_t e = text.find_first_of("eE");
    if (e != std::string_view::npos) return e + 1 < text.size() && text[e + 1] == '-';
    return text.find_first_of("123456789") > text.find('.');
}
#endif

// The whole of `text` as a decimal number (inf and nan too), or nothing.
bool read_decimal(std::string_view text, double& value) {
    if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return false;
#if defined(__EMSCRIPTEN__)
    // Emscripten's libc++ has no floating-point from_chars: strtod (the web
    // build never sets a locale).
    const std::string copy(text);
    char* end = nullptr;
    value = std::strtod(copy.c_str(), &end);
    return end == copy.c_str() + copy.size();
#else
    // from_chars: the same in every locale.
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ptr != text.data() + text.size()) return false;
    if (ec == std::errc::result_out_of_range) {
        value = underflows(text) ? 0.0 : std::numeric_limits<double>::infinity();
        return true;
    }
    return ec == std::errc();
#endif
}

}  // namespace

NumberText read_number_text(std::string_view text) {
    NumberText out;
    std::string_view digits = text;
    if (!digits.empty() && digits[0] == '+') {
        digits.remove_prefix(1);
        if (!digits.empty() && (digits[0] == '-' || digits[0] == '+')) {
            out.problem = "is not a finite number";
            return out;
        }
    }
    if (hexadecimal(digits)) {
        out.problem = "is hexadecimal: write numbers in decimal";
        return out;
    }
    double v = 0.0;
    if (!read_decimal(digits, v) || !std::isfinite(v)) {
        out.problem = "is not a finite number";
        return out;
    }
    // A subnormal or a number below it: 0 (docs/cli.md, "Numbers").
    out.value = std::abs(v) < std::numeric_limits<double>::min() ? 0.0 : v;
    return out;
}

}  // namespace impossible
