// Collects diagnostics while reading a parsed layout, and reads typed values
// (numbers, vectors, colours, ids) with the layout's rules and limits.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "layout/json_doc.hpp"
#include "layout/layout.hpp"

namespace impossible::layout::detail {

using nlohmann::json;

// Where a value is: its JSON pointer (to find its position) and the name a
// message shows ("rooms[1].max").
struct Path {
    std::string pointer;
    std::string display;

    Path operator/(std::string_view key) const;
    Path operator/(std::size_t index) const;
};

// How a number is checked.
enum class NumberKind {
    Coordinate,  // |v| ≤ kMaxCoordinate
    Length,      // kMinLength ≤ v ≤ kMaxLength (must be > 0)
    Angle,       // |v| ≤ kMaxAngleDeg
    Scale,       // kMinScale ≤ v ≤ kMaxScale
    Colour,      // 0 ≤ v ≤ 1, a colour component
    Fraction,    // 0 ≤ v ≤ 1, a share (a window's reflectance)
    Direction,   // |v| ≤ kMaxDirectionComponent (a vector normalised later)
    Time,        // 0 ≤ v ≤ kMaxMotionTime, seconds (a motion key's time)
};

class Checker {
public:
    // `text` is the JSON text that parse_json accepted.
    Checker(std::string_view text, std::string file);

    void error(const Path& at, std::string_view message);         // at the value
    void error_at_key(const Path& at, std::string_view message);  // at its key
    void warning(const Path& at, std::string_view message);
    // A warning that render and trace print too (Layout::model_warnings).
    void model_warning(const Path& at, std::string_view message);
    // A warning that every command loading the layout prints, not only
    // validate (LoadResult::loud_warnings): one that changes what is drawn.
    void loud_warning(const Path& at, std::string_view message);
    void error_at_offset(std::size_t offset, std::string_view message);

    // Unknown fields (other than "_comments") are errors at their key;
    // missing required fields are errors at the object. False if a required
    // field is missing.
    bool check_fields(const Path& at, const json& object, std::initializer_list<const char*> known,
                      std::initializer_list<const char*> required);

    // Typed readers: report an error and return nothing when the value is wrong.
    bool expect_object(const Path& at, const json& value);
    bool expect_array(const Path& at, const json& value, std::size_t max_size);
    std::optional<std::string> read_string(const Path& at, const json& value);
    std::optional<std::string> read_id(const Path& at, const json& value);  // [A-Za-z0-9_-]+
    std::optional<double> read_number(const Path& at, const json& value, NumberKind kind);
    // `shape` names the coordinates in the error: "[x, z]" on the floor,
    // "[u, v]" in an eye's image (a headset's visible area).
    std::optional<glm::dvec2> read_vec2(const Path& at, const json& value, NumberKind kind,
                                        const char* shape = "[x, z]");
    std::optional<glm::dvec3> read_vec3(const Path& at, const json& value, NumberKind kind);
    std::optional<glm::dvec3> read_colour(const Path& at, const json& value);

    bool has_errors() const { return !errors_.empty(); }

    // The diagnostics with line and column, each list sorted in file order.
    std::vector<Diagnostic> take_errors() const;
    std::vector<Diagnostic> take_warnings() const;
    std::vector<Diagnostic> take_model_warnings() const;  // those of model_warning only
    std::vector<Diagnostic> take_loud_warnings() const;

    std::size_t offset_of(const Path& at) const;  // of the value, or its nearest ancestor

private:
    struct Pending {
        std::size_t offset = kNoOffset;
        std::string message;
        bool model = false;  // model_warning's
    };

    std::string_view text_;
    std::string file_;
    mutable std::optional<ValuePositions> positions_;  // made for the first problem (json_doc.hpp)
    std::vector<Pending> errors_;
    std::vector<Pending> warnings_;
    std::vector<Pending> loud_warnings_;  // also in warnings_

    const ValuePositions& positions() const;
    std::size_t key_offset_of(const Path& at) const;
    std::vector<Diagnostic> finish(std::vector<Pending> pending) const;
};

// "a string", "an array", ... for "got ..." in messages.
std::string json_type_name(const json& value);

// The field of an object, or null if absent.
const json* field(const json& object, const char* name);

}  // namespace impossible::layout::detail
