#include "layout/checker.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "base/file_io.hpp"
#include "base/format.hpp"
#include "base/user_text.hpp"
#include "layout/limits.hpp"

namespace impossible::layout::detail {

namespace {

bool is_identifier_key(std::string_view key) {
    if (key.empty()) return false;
    return std::all_of(key.begin(), key.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
               c == '+';
    });
}

// Edit distance, for "did you mean" hints on unknown fields (short names
// only): insertions, deletions, substitutions, and swaps of two neighbouring
// letters, each one edit (the optimal string alignment distance), so that
// "knid" is one edit from "kind".
std::size_t edit_distance(std::string_view a, std::string_view b) {
    const std::size_t w = b.size() + 1;
    std::vector<std::size_t> d((a.size() + 1) * w);
    for (std::size_t i = 0; i <= a.size(); ++i) d[i * w] = i;
    for (std::size_t j = 0; j <= b.size(); ++j) d[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        for (std::size_t j = 1; j <= b.size(); ++j) {
            std::size_t v = std::min(
                {d[(i - 1) * w + j] + 1, d[i * w + j - 1] + 1, d[(i - 1) * w + j - 1] + (a[i - 1] != b[j - 1])});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                v = std::min(v, d[(i - 2) * w + j - 2] + 1);
            d[i * w + j] = v;
        }
    }
    return d.back();
}

// What is wrong with a colour component, a share or a time `v` (written
// `shown`), or nothing.
std::optional<std::string> range_problem(NumberKind kind, double v, const std::string& shown) {
    switch (kind) {
        case NumberKind::Colour:
            if (v < 0.0 || v > 1.0) return "colour component " + shown + " is outside 0..1";
            break;
        case NumberKind::Fraction:
            if (v < 0.0 || v > 1.0) return "must be in 0..1 (got " + shown + ")";
            break;
        case NumberKind::Time:
            if (v < 0.0) return "must not be negative (got " + shown + ")";
            if (v > limits::kMaxMotionTime)
                return shown + " is too large (the maximum is " + format_number(limits::kMaxMotionTime) + " s)";
            break;
        default: break;
    }
    return std::nullopt;
}

}  // namespace

Path Path::operator/(std::string_view key) const {
    Path out;
    out.pointer = pointer + "/" + pointer_token(key);
    if (is_identifier_key(key) && key.size() <= kQuotedCharacters) {
        out.display = display.empty() ? std::string(key) : display + "." + std::string(key);
    } else {
        out.display = display + "[" + quote(key) + "]";
    }
    return out;
}

Path Path::operator/(std::size_t index) const {
    return {pointer + "/" + std::to_string(index), display + "[" + std::to_string(index) + "]"};
}

std::string json_type_name(const json& value) {
    switch (value.type()) {
        case json::value_t::null: return "null";
        case json::value_t::boolean: return "a boolean";
        case json::value_t::string: return "a string";
        case json::value_t::array: return "an array";
        case json::value_t::object: return "an object";
        case json::value_t::number_integer:
        case json::value_t::number_unsigned:
        case json::value_t::number_float: return "a number";
        default: return "an unknown value";
    }
}

const json* field(const json& object, const char* name) {
    if (!object.is_object()) return nullptr;
    const auto it = object.find(name);
    return it == object.end() ? nullptr : &*it;
}

Checker::Checker(std::string_view text, std::string file) : text_(text), file_(std::move(file)) {}

const ValuePositions& Checker::positions() const {
    if (!positions_) positions_ = value_positions(text_);
    return *positions_;
}

std::size_t Checker::offset_of(const Path& at) const {
    std::string pointer = at.pointer;
    for (;;) {
        const auto it = positions().find(pointer);
        if (it != positions().end()) return it->second.value;
        if (pointer.empty()) return kNoOffset;
        pointer.erase(pointer.rfind('/'));
    }
}

std::size_t Checker::key_offset_of(const Path& at) const {
    const auto it = positions().find(at.pointer);
    if (it != positions().end() && it->second.key != kNoOffset) return it->second.key;
    return offset_of(at);
}

static std::string with_name(const Path& at, std::string_view message) {
    if (at.display.empty()) return std::string(message);
    return at.display + ": " + std::string(message);
}

void Checker::error(const Path& at, std::string_view message) {
    errors_.push_back({offset_of(at), with_name(at, message)});
}

void Checker::error_at_key(const Path& at, std::string_view message) {
    errors_.push_back({key_offset_of(at), with_name(at, message)});
}

void Checker::warning(const Path& at, std::string_view message) {
    warnings_.push_back({offset_of(at), with_name(at, message)});
}

void Checker::model_warning(const Path& at, std::string_view message) {
    warnings_.push_back({offset_of(at), with_name(at, message), true});
}

void Checker::loud_warning(const Path& at, std::string_view message) {
    warning(at, message);
    loud_warnings_.push_back(warnings_.back());
}

void Checker::error_at_offset(std::size_t offset, std::string_view message) {
    errors_.push_back({offset, std::string(message)});
}

std::vector<Diagnostic> Checker::finish(std::vector<Pending> pending) const {
    // File order; problems without a position first. Stable: equal positions
    // keep the order in which they were found.
    std::stable_sort(pending.begin(), pending.end(), [](const Pending& a, const Pending& b) {
        const auto key = [](std::size_t o) { return o == kNoOffset ? std::size_t{0} : o + 1; };
        return key(a.offset) < key(b.offset);
    });
    std::vector<std::size_t> offsets;
    for (const Pending& p : pending) {
        if (p.offset != kNoOffset) offsets.push_back(p.offset);
    }
    const std::vector<TextPosition> positions = text_positions(text_, offsets);
    std::vector<Diagnostic> out;
    std::size_t next = 0;
    for (Pending& p : pending) {
        Diagnostic d;
        d.file = file_;
        if (p.offset != kNoOffset) {
            d.line = positions[next].line;
            d.column = positions[next].column;
            ++next;
        }
        d.message = std::move(p.message);
        out.push_back(std::move(d));
    }
    return out;
}

std::vector<Diagnostic> Checker::take_errors() const { return finish(errors_); }
std::vector<Diagnostic> Checker::take_warnings() const { return finish(warnings_); }
std::vector<Diagnostic> Checker::take_model_warnings() const {
    std::vector<Pending> model;
    std::copy_if(warnings_.begin(), warnings_.end(), std::back_inserter(model),
                 [](const Pending& p) { return p.model; });
    return finish(model);
}

std::vector<Diagnostic> Checker::take_loud_warnings() const { return finish(loud_warnings_); }

bool Checker::check_fields(const Path& at, const json& object, std::initializer_list<const char*> known,
                           std::initializer_list<const char*> required) {
    for (auto it = object.begin(); it != object.end(); ++it) {
        const std::string& key = it.key();
        if (!key.empty() && key.front() == '_') continue;  // a comment
        const bool is_known = std::any_of(known.begin(), known.end(), [&](const char* k) { return key == k; });
        if (is_known) continue;
        std::string message = "unknown field " + quote(key);
        // The closest known name within two edits ("knid" is "kind", not "id");
        // on a tie, the first listed.
        const char* hint = nullptr;
        std::size_t best = 3;
        for (const char* k : known) {
            const std::size_t d = key.size() < 40 ? edit_distance(key, k) : best;
            if (d < best) best = d, hint = k;
        }
        if (hint != nullptr) message += " (did you mean " + quote(hint) + "?)";
        error_at_key(at / key, message);
    }
    bool complete = true;
    for (const char* name : required) {
        if (!object.contains(name)) {
            error(at, "missing required field " + quote(name));
            complete = false;
        }
    }
    return complete;
}

bool Checker::expect_object(const Path& at, const json& value) {
    if (value.is_object()) return true;
    error(at, "must be an object (got " + json_type_name(value) + ")");
    return false;
}

bool Checker::expect_array(const Path& at, const json& value, std::size_t max_size) {
    if (!value.is_array()) {
        error(at, "must be an array (got " + json_type_name(value) + ")");
        return false;
    }
    if (value.size() > max_size) {
        error(at,
              "has " + std::to_string(value.size()) + " entries; at most " + std::to_string(max_size) + " are allowed");
        return false;
    }
    return true;
}

std::optional<std::string> Checker::read_string(const Path& at, const json& value) {
    if (!value.is_string()) {
        error(at, "must be a string (got " + json_type_name(value) + ")");
        return std::nullopt;
    }
    return value.get<std::string>();
}

std::optional<std::string> Checker::read_id(const Path& at, const json& value) {
    std::optional<std::string> id = read_string(at, value);
    if (!id) return std::nullopt;
    const bool ok = !id->empty() && std::all_of(id->begin(), id->end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
    });
    if (!ok) {
        error(at, "id " + quote(*id) + " must be letters, digits, '_' and '-' only ([A-Za-z0-9_-]+)");
        return std::nullopt;
    }
    return id;
}

std::optional<double> Checker::read_number(const Path& at, const json& value, NumberKind kind) {
    if (!value.is_number()) {
        error(at, "must be a number (got " + json_type_name(value) + ")");
        return std::nullopt;
    }
    const double v = value.get<double>();
    const std::string shown = format_number(v);
    if (!std::isfinite(v)) {
        error(at, "must be a finite number (got " + shown + ")");
        return std::nullopt;
    }
    const auto out_of_range = [&](double limit, const char* unit) {
        error(at, shown + " is out of range (|value| must be at most " + format_number(limit) + unit + ")");
        return std::nullopt;
    };
    const auto at_least = [&](double low, double high, const char* unit) -> std::optional<double> {
        if (v <= 0.0) {
            error(at, "must be greater than 0 (got " + shown + ")");
            return std::nullopt;
        }
        if (v < low) {
            error(at, shown + " is too small (the minimum is " + format_number(low) + unit + ")");
            return std::nullopt;
        }
        if (v > high) {
            error(at, shown + " is too large (the maximum is " + format_number(high) + unit + ")");
            return std::nullopt;
        }
        return v;
    };
    switch (kind) {
        case NumberKind::Coordinate:
            if (std::abs(v) > limits::kMaxCoordinate) return out_of_range(limits::kMaxCoordinate, " m");
            return v;
        case NumberKind::Direction:
            if (std::abs(v) > limits::kMaxDirectionComponent) {
                return out_of_range(limits::kMaxDirectionComponent, "");
            }
            return v;
        case NumberKind::Angle:
            if (std::abs(v) > limits::kMaxAngleDeg) return out_of_range(limits::kMaxAngleDeg, " degrees");
            return v;
        case NumberKind::Length: return at_least(limits::kMinLength, limits::kMaxLength, " m");
        case NumberKind::Scale: return at_least(limits::kMinScale, limits::kMaxScale, "");
        case NumberKind::Colour:
        case NumberKind::Fraction:
        case NumberKind::Time:
            if (const std::optional<std::string> problem = range_problem(kind, v, shown)) {
                error(at, *problem);
                return std::nullopt;
            }
            return v;
    }
    return std::nullopt;
}

std::optional<glm::dvec2> Checker::read_vec2(const Path& at, const json& value, NumberKind kind, const char* shape) {
    if (!value.is_array() || value.size() != 2) {
        const std::string got =
            value.is_array() ? "an array of " + std::to_string(value.size()) : json_type_name(value);
        error(at, std::string("must be an array of 2 numbers ") + shape + " (got " + got + ")");
        return std::nullopt;
    }
    const auto x = read_number(at / 0, value[0], kind);
    const auto z = read_number(at / 1, value[1], kind);
    if (!x || !z) return std::nullopt;
    return glm::dvec2(*x, *z);
}

std::optional<glm::dvec3> Checker::read_vec3(const Path& at, const json& value, NumberKind kind) {
    const char* shape = kind == NumberKind::Colour ? "[r, g, b]" : "[x, y, z]";
    if (!value.is_array() || value.size() != 3) {
        const std::string got =
            value.is_array() ? "an array of " + std::to_string(value.size()) : json_type_name(value);
        error(at, std::string("must be an array of 3 numbers ") + shape + " (got " + got + ")");
        return std::nullopt;
    }
    const auto x = read_number(at / 0, value[0], kind);
    const auto y = read_number(at / 1, value[1], kind);
    const auto z = read_number(at / 2, value[2], kind);
    if (!x || !y || !z) return std::nullopt;
    return glm::dvec3(*x, *y, *z);
}

std::optional<glm::dvec3> Checker::read_colour(const Path& at, const json& value) {
    return read_vec3(at, value, NumberKind::Colour);
}

}  // namespace impossible::layout::detail
