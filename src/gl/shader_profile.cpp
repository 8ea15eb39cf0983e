#include "gl/shader_profile.hpp"

#include <cctype>

namespace impossible::gl {

namespace {

bool is_word(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::size_t skip_space(const std::string& s, std::size_t i) {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    return i;
}

std::size_t word_end(const std::string& s, std::size_t i) {
    while (i < s.size() && is_word(s[i])) ++i;
    return i;
}

std::string trim(const std::string& s) {
    const std::size_t a = skip_space(s, 0);
    std::size_t b = s.size();
    while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
    return s.substr(a, b - a);
}

}  // namespace

std::string strip_layout_bindings(const std::string& text, std::vector<NamedBinding>& bindings) {
    std::string out;
    std::size_t copied = 0;
    for (std::size_t at = text.find("layout"); at != std::string::npos; at = text.find("layout", at + 1)) {
        if (at > 0 && is_word(text[at - 1])) continue;
        const std::size_t open = skip_space(text, at + 6);
        if (open >= text.size() || text[open] != '(') continue;
        const std::size_t close = text.find(')', open);
        if (close == std::string::npos) break;
        // The qualifiers, and which of them is the binding.
        std::vector<std::string> kept;
        int binding = -1;
        std::size_t from = open + 1;
        while (from <= close) {
            std::size_t comma = text.find(',', from);
            if (comma == std::string::npos || comma > close) comma = close;
            const std::string item = trim(text.substr(from, comma - from));
            const std::size_t eq = item.find('=');
            if (eq != std::string::npos && trim(item.substr(0, eq)) == "binding")
                binding = std::stoi(trim(item.substr(eq + 1)));
            else if (!item.empty())
                kept.push_back(item);
            from = comma + 1;
        }
        if (binding < 0) continue;
        // uniform <type or block name> [<name>]
        std::size_t i = skip_space(text, close + 1);
        if (text.compare(i, 7, "uniform") != 0) continue;
        i = skip_space(text, i + 7);
        const std::size_t type_end = word_end(text, i);
        const std::string type = text.substr(i, type_end - i);
        const std::size_t name_at = skip_space(text, type_end);
        const std::string name = text.substr(name_at, word_end(text, name_at) - name_at);
        const bool sampler = type.find("sampler") != std::string::npos;
        bindings.push_back({sampler ? name : type, binding, !sampler});
        out.append(text, copied, at - copied);
        if (!kept.empty()) {
            out += "layout(";
            for (std::size_t k = 0; k < kept.size(); ++k) out += (k ? ", " : "") + kept[k];
            out += ") ";
        }
        copied = skip_space(text, close + 1);
    }
    out.append(text, copied, std::string::npos);
    return out;
}

std::string profile_source(const std::string& defines, const std::string& text, std::vector<NamedBinding>& bindings) {
#if defined(__EMSCRIPTEN__)
    // "#line 1" keeps the driver's line numbers those of the file.
    return "#version 300 es\n"
           "#extension GL_ANGLE_clip_cull_distance : enable\n"
           "precision highp float;\nprecision highp int;\nprecision highp usampler2D;\n"
           "precision highp sampler2DArray;\nprecision highp sampler2DShadow;\n"
           "#define WEBGL 1\n" +
           defines + "\n#line 1\n" + strip_layout_bindings(text, bindings);
#else
    (void)bindings;
    return "#version 450 core\n" + defines + "\n#line 1\n" + text;
#endif
}

}  // namespace impossible::gl
