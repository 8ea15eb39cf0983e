// JSON text parsed with nlohmann::json, plus where each value starts.
//
// nlohmann reports byte offsets only for syntax errors; semantic errors need
// the position of any value, so a second pass over the (then known valid)
// text finds repeated keys, and value_positions records the byte offset of
// every value and object key, keyed by JSON pointer (RFC 6901:
// "/rooms/1/max"), when a problem must be placed.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <nlohmann/json.hpp>

namespace impossible::layout::detail {

inline constexpr std::size_t kNoOffset = static_cast<std::size_t>(-1);

struct ValuePosition {
    std::size_t value = kNoOffset;  // byte offset of the value's first character
    std::size_t key = kNoOffset;    // byte offset of its key's opening quote, if any
};

// A key that appears twice in one object (the later value wins in `root`).
struct DuplicateKey {
    std::string pointer;  // of the later value
    std::size_t key = kNoOffset;
    std::size_t first_key = kNoOffset;
};

struct JsonDocument {
    nlohmann::json root;
    std::vector<DuplicateKey> duplicates;
};

// Where every value of JSON text that parse_json accepted starts, by JSON
// pointer (empty for other text). A valid layout never needs it, so it is
// made only for the first problem to report: on large files it was a third
// of the load time.
using ValuePositions = std::unordered_map<std::string, ValuePosition>;
ValuePositions value_positions(std::string_view text);

struct JsonError {
    std::size_t offset = 0;  // byte offset of the offending character
    std::string message;
};

struct JsonParse {
    std::optional<JsonDocument> document;  // set exactly when error is not
    std::optional<JsonError> error;
};

// Parses one JSON value (RFC 8259, no comments) from text. Never throws for
// bad input; enforces limits::kMaxDepth and limits::kMaxValues.
JsonParse parse_json(std::string_view text);

// A key as one JSON pointer reference token ("~" → "~0", "/" → "~1").
std::string pointer_token(std::string_view key);

}  // namespace impossible::layout::detail
