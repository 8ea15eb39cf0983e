#include "layout/json_doc.hpp"

#include <algorithm>
#include <utility>

#include "base/file_io.hpp"
#include "base/format.hpp"
#include "base/user_text.hpp"
#include "layout/limits.hpp"

namespace impossible::layout::detail {

using nlohmann::json;

namespace {

// Builds the DOM from nlohmann's SAX events (its own DOM builder cannot
// report the byte offset of a number overflow, nor stop at our limits).
class DomBuilder {
public:
    json root;
    bool limit_passed = false;
    std::optional<JsonError> error;

    bool null() { return place(json(nullptr)) != nullptr; }
    bool boolean(bool v) { return place(json(v)) != nullptr; }
    bool number_integer(json::number_integer_t v) { return place(json(v)) != nullptr; }
    bool number_unsigned(json::number_unsigned_t v) { return place(json(v)) != nullptr; }
    bool number_float(json::number_float_t v, const json::string_t&) { return place(json(v)) != nullptr; }
    bool string(json::string_t& v) { return place(json(std::move(v))) != nullptr; }
    bool binary(json::binary_t&) { return false; }  // never produced by JSON text
    bool start_object(std::size_t) { return open(json::value_t::object); }
    bool key(json::string_t& k) {
        key_ = std::move(k);
        return true;
    }
    bool end_object() { return close(); }
    bool start_array(std::size_t) { return open(json::value_t::array); }
    bool end_array() { return close(); }

    bool parse_error(std::size_t position, const std::string&, const json::exception& e) {
        JsonError out;
        out.offset = position > 0 ? position - 1 : 0;  // where nlohmann noticed
        out.message = clean_message(e.what());
        error = std::move(out);
        return false;
    }

private:
    std::vector<json*> stack_;  // the open containers (their addresses are stable)
    std::string key_;
    std::size_t values_ = 0;

    json* place(json&& value) {
        if (++values_ > limits::kMaxValues) {
            limit_passed = true;
            return nullptr;
        }
        if (stack_.empty()) {
            root = std::move(value);
            return &root;
        }
        json& top = *stack_.back();
        if (top.is_array()) {
            top.get_ref<json::array_t&>().push_back(std::move(value));
            return &top.get_ref<json::array_t&>().back();
        }
        json& slot = top[key_];  // a repeated key: the later value wins
        slot = std::move(value);
        return &slot;
    }

    bool open(json::value_t type) {
        if (stack_.size() >= limits::kMaxDepth) {
            limit_passed = true;
            return false;
        }
        json* container = place(json(type));
        if (container == nullptr) return false;
        stack_.push_back(container);
        return true;
    }

    bool close() {
        if (!stack_.empty()) stack_.pop_back();
        return true;
    }

    // "[json.exception.parse_error.101] parse error at line 1, column 2:
    // syntax error ... - invalid literal; last read: 'x'; expected ..." → the
    // part after the position, without the token (our own position is exact).
    static std::string clean_message(std::string message) {
        if (!message.empty() && message.front() == '[') {
            const std::size_t end = message.find("] ");
            if (end != std::string::npos) message.erase(0, end + 2);
        }
        if (message.rfind("parse error", 0) == 0) {
            const std::size_t colon = message.find(": ");
            if (colon != std::string::npos) message.erase(0, colon + 2);
        }
        const std::size_t last_read = message.find("; last read: '");
        if (last_read != std::string::npos) {
            const std::size_t expected = message.find("'; expected ", last_read);
            if (expected != std::string::npos) {
                message.erase(last_read, expected + 1 - last_read);
            } else {
                message.erase(last_read);
            }
        }
        return "invalid JSON: " + printable(message, 2 * kQuotedCharacters);
    }
};

bool is_number_char(char c) {
    return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
}

bool is_literal_char(char c) { return is_number_char(c) || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

// nlohmann reports where it noticed a problem: for a bad literal or number
// that is past its start ("tru}" at the "}"), for a misplaced string at its
// closing quote. Point at the start of such a token instead; problems inside
// a string stay where they are (the bad byte or escape).
std::size_t token_start(std::string_view text, std::size_t noticed, const std::string& message) {
    if (noticed > text.size()) noticed = text.size();
    const bool bad_token = message.find("invalid literal") != std::string::npos ||
                           message.find("invalid number") != std::string::npos ||
                           message.find("number overflow") != std::string::npos;
    if (bad_token) {
        std::size_t start = noticed;
        if (start < text.size() && is_literal_char(text[start])) ++start;
        while (start > 0 && is_literal_char(text[start - 1])) --start;
        return start;
    }
    if (message.find("ill-formed UTF-8") != std::string::npos && noticed < text.size() &&
        static_cast<unsigned char>(text[noticed]) < 0x80) {
        // An ASCII byte cut a multi-byte sequence short: point at its lead byte.
        std::size_t start = noticed;
        while (start > 0 && (static_cast<unsigned char>(text[start - 1]) & 0xC0) == 0x80) --start;
        if (start > 0 && (static_cast<unsigned char>(text[start - 1]) & 0xC0) == 0xC0) --start;
        return start;
    }
    if (message.find("unexpected string literal") != std::string::npos && noticed < text.size() &&
        text[noticed] == '"') {
        const std::size_t open = text.rfind('"', noticed == 0 ? 0 : noticed - 1);
        return open == std::string_view::npos ? noticed : open;
    }
    return noticed;
}

// A bad literal that is NaN or an infinity as JavaScript and Python's json
// write them: named, since JSON has no such numbers (issue 38).
std::string non_finite_note(std::string_view text, std::size_t start) {
    for (std::string_view word : {"NaN", "Infinity", "-Infinity", "nan", "inf", "-inf"}) {
        const std::string_view at = text.substr(std::min(start, text.size()), word.size() + 1);
        if (at.substr(0, word.size()) == word && (at.size() == word.size() || !is_literal_char(at.back())))
            return " (" + std::string(word) + ": JSON has no NaN or infinity; every number must be finite)";
    }
    return {};
}

// Walks JSON text and records where every value and key starts. It is exact
// on valid JSON and harmless (bounds-checked, bounded) on anything else; on
// text that passes a limit it stops at the value that passed it.
class PositionScanner {
public:
    // Records positions and repeated keys into what is not null.
    PositionScanner(std::string_view text, ValuePositions* positions, std::vector<DuplicateKey>* duplicates)
        : text_(text), positions_(positions), duplicates_(duplicates) {}

    std::size_t limit_offset = kNoOffset;
    std::string limit_reason;

    // False where the text is not valid JSON or a limit was passed.
    bool run() {
        if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;
        skip_space();
        std::string pointer;
        std::size_t key = kNoOffset;
        for (;;) {
            if (!value(pointer, key)) return false;
            // After a value: close containers until a comma or the end.
            for (;;) {
                skip_space();
                if (stack_.empty()) return pos_ == text_.size();
                if (pos_ >= text_.size()) return false;
                Frame& frame = stack_.back();
                const char c = text_[pos_];
                if (c == (frame.object ? '}' : ']')) {
                    ++pos_;
                    stack_.pop_back();
                    continue;
                }
                if (c != ',') return false;
                ++pos_;
                skip_space();
                if (!next_member(pointer, key)) return false;
                break;
            }
        }
    }

private:
    struct Frame {
        bool object = false;
        std::size_t index = 0;
        std::string pointer;
        std::unordered_map<std::string, std::size_t> keys;  // key → offset
    };

    std::string_view text_;
    ValuePositions* positions_;
    std::vector<DuplicateKey>* duplicates_;
    std::size_t pos_ = 0;
    std::size_t values_ = 0;
    std::vector<Frame> stack_;

    void skip_space() {
        while (pos_ < text_.size() &&
               (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\n' || text_[pos_] == '\r')) {
            ++pos_;
        }
    }

    // Reads one value; for a non-empty container, stops at its first member.
    bool value(std::string& pointer, std::size_t& key) {
        if (pos_ >= text_.size()) return false;
        if (++values_ > limits::kMaxValues) {
            limit_offset = pos_;
            limit_reason = "the JSON holds more than " + std::to_string(limits::kMaxValues) + " values";
            return false;
        }
        if (positions_ != nullptr) (*positions_)[pointer] = {pos_, key};
        const char c = text_[pos_];
        if (c == '{' || c == '[') {
            if (stack_.size() >= limits::kMaxDepth) {
                limit_offset = pos_;
                limit_reason = "the JSON is nested deeper than " + std::to_string(limits::kMaxDepth) + " levels";
                return false;
            }
            Frame frame;
            frame.object = c == '{';
            frame.pointer = pointer;
            stack_.push_back(std::move(frame));
            ++pos_;
            skip_space();
            if (pos_ < text_.size() && text_[pos_] == (c == '{' ? '}' : ']')) {
                ++pos_;
                stack_.pop_back();
                return true;
            }
            stack_.back().index = static_cast<std::size_t>(-1);
            if (!next_member(pointer, key)) return false;
            return value(pointer, key);
        }
        if (c == '"') return skip_string();
        const std::size_t start = pos_;
        while (pos_ < text_.size() && (is_number_char(text_[pos_]) || (text_[pos_] >= 'a' && text_[pos_] <= 'z'))) {
            ++pos_;
        }
        return pos_ > start;
    }

    // Sets pointer/key for the next member of the innermost container.
    bool next_member(std::string& pointer, std::size_t& key) {
        Frame& frame = stack_.back();
        ++frame.index;
        if (!frame.object) {
            pointer = frame.pointer + "/" + std::to_string(frame.index);
            key = kNoOffset;
            return true;
        }
        if (pos_ >= text_.size() || text_[pos_] != '"') return false;
        key = pos_;
        if (!skip_string()) return false;
        std::string name;
        if (!decode_string(text_.substr(key, pos_ - key), name)) return false;
        skip_space();
        if (pos_ >= text_.size() || text_[pos_] != ':') return false;
        ++pos_;
        skip_space();
        const auto [first, inserted] = frame.keys.emplace(name, key);
        pointer = frame.pointer + "/" + pointer_token(name);
        if (!inserted && duplicates_ != nullptr) duplicates_->push_back({pointer, key, first->second});
        return true;
    }

    bool skip_string() {
        ++pos_;  // the opening quote
        while (pos_ < text_.size()) {
            const char c = text_[pos_];
            if (c == '\\') {
                pos_ += 2;
            } else if (c == '"') {
                ++pos_;
                return true;
            } else {
                ++pos_;
            }
        }
        return false;
    }

    static bool decode_string(std::string_view token, std::string& out) {
        if (token.find('\\') == std::string_view::npos) {
            out.assign(token.substr(1, token.size() - 2));
            return true;
        }
        const json decoded = json::parse(token, nullptr, /*allow_exceptions=*/false);
        if (!decoded.is_string()) return false;
        out = decoded.get<std::string>();
        return true;
    }
};

}  // namespace

std::string pointer_token(std::string_view key) {
    std::string out;
    out.reserve(key.size());
    for (const char c : key) {
        if (c == '~') {
            out += "~0";
        } else if (c == '/') {
            out += "~1";
        } else {
            out += c;
        }
    }
    return out;
}

JsonParse parse_json(std::string_view text) {
    JsonParse result;
    // nlohmann's lexer takes a NUL byte for the end of the input, so
    // "{...}\0garbage" would parse; a layout is text and holds none.
    if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos) {
        result.error = JsonError{nul, "a NUL byte (\\x00): a layout is JSON text, which cannot hold one"};
        return result;
    }
    DomBuilder builder;
    const bool parsed = json::sax_parse(text.begin(), text.end(), &builder, json::input_format_t::json, /*strict=*/true,
                                        /*ignore_comments=*/false);
    if (!parsed) {
        if (builder.error) {
            JsonError error = *builder.error;
            error.offset = token_start(text, error.offset, error.message);
            error.message += non_finite_note(text, error.offset);
            result.error = std::move(error);
        } else {
            PositionScanner scanner(text, nullptr, nullptr);
            scanner.run();
            JsonError error;
            error.offset = scanner.limit_offset == kNoOffset ? 0 : scanner.limit_offset;
            error.message = scanner.limit_reason.empty() ? "the JSON passes a size limit" : scanner.limit_reason;
            result.error = std::move(error);
        }
        return result;
    }
    JsonDocument document;
    document.root = std::move(builder.root);
    PositionScanner scanner(text, nullptr, &document.duplicates);
    if (!scanner.run()) {
        // Cannot happen for text nlohmann accepted; keep going without them.
        document.duplicates.clear();
    }
    result.document = std::move(document);
    return result;
}

ValuePositions value_positions(std::string_view text) {
    ValuePositions positions;
    PositionScanner scanner(text, &positions, nullptr);
    if (!scanner.run()) positions.clear();
    return positions;
}

}  // namespace impossible::layout::detail
