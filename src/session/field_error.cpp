#include "session/field_error.hpp"

namespace impossible::session {

std::string spell_fields(const std::string& message, const FieldNamer& namer) {
    std::string out;
    std::size_t at = 0;
    while (at < message.size()) {
        const std::size_t open = message.find('{', at);
        const std::size_t close = open == std::string::npos ? open : message.find('}', open);
        if (close == std::string::npos) break;
        out += message.substr(at, open - at) + namer(message.substr(open + 1, close - open - 1));
        at = close + 1;
    }
    return out + message.substr(std::min(at, message.size()));
}

std::string library_field(const std::string& field) { return field == "no_cull" ? "cull = false" : field; }

std::string library_message(const FieldError& error) {
    const std::string text = spell_fields(error.message, library_field);
    return error.kind == FieldError::Kind::Value ? error.field + " " + text : text;
}

std::string command_message(const FieldError& error, const FieldNamer& flag_of) {
    return flag_of(error.field) + ": " + spell_fields(error.message, flag_of);
}

}  // namespace impossible::session
