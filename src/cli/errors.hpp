// How a command fails (cli.md, "Exit statuses"): a usage error (exit 2) or
// wrong input (exit 1), thrown as exceptions that the dispatcher (app/run_main.cpp)
// turns into one line on standard error and the status. Below the command
// line, failures are Result<T> (base/result.hpp); value_or_throw and check
// are the one bridge from those to InputError.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "base/result.hpp"

namespace impossible::cli {

// Exit statuses of cli.md.
inline constexpr int kExitOk = 0;
inline constexpr int kExitBadInput = 1;
inline constexpr int kExitUsage = 2;

// A usage error (unknown option, missing value): exit status 2.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};
// Wrong input (bad value, bad layout, unknown room): exit status 1.
struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The message of a failed result, after "CONTEXT: " when a context is given
// (a path, "no OpenGL 4.5 context").
inline std::string error_message(const std::string& error, std::string_view context) {
    if (context.empty()) return error;
    std::string message(context);
    message += ": ";
    message += error;
    return message;
}

// The value of a result, or InputError with its message.
template <class T>
T value_or_throw(Result<T>&& result, std::string_view context = {}) {
    if (!result) throw InputError(error_message(result.error(), context));
    return std::move(result).value();
}

// Nothing, or InputError with the result's message.
inline void check(const Result<void>& result, std::string_view context = {}) {
    if (!result) throw InputError(error_message(result.error(), context));
}
// A result with a value is not checked and dropped: use value_or_throw.
template <class T>
void check(const Result<T>& result, std::string_view context = {}) = delete;

}  // namespace impossible::cli
