// The command line's names for the library's settings: each field of
// math::View, render::Technique and render::Diagnostics that has a flag,
// and the one function that spells the session's and the renderer's
// messages ("{max_depth}") with them ("--max-depth").
#pragma once

#include <string>
#include <utility>

#include "base/result.hpp"

#include "session/field_error.hpp"

namespace impossible::cli {

// The flag of a field ("max_depth" → "--max-depth", "cull_portals" →
// "--no-cull"); a field with no flag of its own is spelled as itself.
std::string flag_of(const std::string& field);

// `message` with each {field} spelled as its flag.
std::string with_flags(const std::string& message);

// A failed result's message with its fields spelled as flags (the renderer's
// errors: "{samples} 3: ..." → "--samples 3: ...").
template <class T>
Result<T> with_flags(Result<T>&& result) {
    if (result) return std::move(result);
    return Error{with_flags(result.error())};
}

// "--max-depth: 300 is not in 0..250".
std::string flag_message(const session::FieldError& error);

}  // namespace impossible::cli
