// The one result type for fallible creation and loading: a value, or a message
// for a human. Shaped like C++23's std::expected<T, std::string> (has_value,
// value, error, operator*, operator->), so it can be swapped for it later.
//
// Use it at I/O and driver boundaries (files, GL objects, windows); internal
// invariants are asserts, not results.
#pragma once

#include <cassert>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

namespace impossible {

// The failure side, so `return Error{"..."};` reads as what it is.
struct Error {
    std::string message;
};

template <class T>
class Result;

template <class T>
class [[nodiscard]] Result {
public:
    Result(T value) : state_(std::in_place_index<0>, std::move(value)) {}              // NOLINT: implicit on purpose
    Result(Error error) : state_(std::in_place_index<1>, std::move(error.message)) {}  // NOLINT
    // A failed result of another type passes its error on: `if (!r) return r;`.
    template <class U>
    requires(!std::is_same_v<U, T>) Result(const Result<U>& failed)
        : Result(Error{failed.error()}) {}  // NOLINT: implicit on purpose

    bool has_value() const { return state_.index() == 0; }
    explicit operator bool() const { return has_value(); }

    T& value() & {
        assert(has_value());
        return std::get<0>(state_);
    }
    const T& value() const& {
        assert(has_value());
        return std::get<0>(state_);
    }
    T&& value() && {
        assert(has_value());
        return std::get<0>(std::move(state_));
    }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }
    T&& operator*() && { return std::move(*this).value(); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }

    const std::string& error() const {
        assert(!has_value());
        return std::get<1>(state_);
    }

private:
    std::variant<T, std::string> state_;
};

// For operations that produce nothing but can fail.
template <>
class [[nodiscard]] Result<void> {
public:
    Result() = default;
    Result(Error error) : error_(std::move(error.message)), failed_(true) {}  // NOLINT
    // A failed result of another type passes its error on: `if (!r) return r;`.
    template <class U>
    Result(const Result<U>& failed) : Result(Error{failed.error()}) {}  // NOLINT: implicit on purpose

    bool has_value() const { return !failed_; }
    explicit operator bool() const { return has_value(); }
    const std::string& error() const {
        assert(failed_);
        return error_;
    }

private:
    std::string error_;
    bool failed_ = false;
};

}  // namespace impossible
