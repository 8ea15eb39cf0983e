// value_or_throw and check: the one bridge from Result<T> to the command
// line's InputError (exit status 1), with the message and an optional context.
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "cli/errors.hpp"

namespace impossible::cli {
namespace {

std::string message_of(void (*f)()) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no InputError)";
}

TEST(CliErrors, ValueOrThrowGivesTheValue) {
    EXPECT_EQ(value_or_throw(Result<int>(7)), 7);
    // Moved out: a move-only value works.
    std::unique_ptr<int> p = value_or_throw(Result<std::unique_ptr<int>>(std::make_unique<int>(3)));
    EXPECT_EQ(*p, 3);
}

TEST(CliErrors, ValueOrThrowThrowsTheMessage) {
    EXPECT_EQ(message_of([] { (void)value_or_throw(Result<int>(Error{"x.png: not a PNG"})); }), "x.png: not a PNG");
    EXPECT_EQ(message_of([] { (void)value_or_throw(Result<int>(Error{"EGL failed"}), "no OpenGL 4.5 context"); }),
              "no OpenGL 4.5 context: EGL failed");
}

TEST(CliErrors, CheckThrowsOnlyOnFailure) {
    EXPECT_NO_THROW(check(Result<void>()));
    EXPECT_EQ(message_of([] { check(Result<void>(Error{"cannot write"})); }), "cannot write");
    EXPECT_EQ(message_of([] { check(Result<void>(Error{"disk full"}), "out.png"); }), "out.png: disk full");
}

TEST(CliErrors, ExitStatusesAreThoseOfCliMd) {
    EXPECT_EQ(kExitOk, 0);
    EXPECT_EQ(kExitBadInput, 1);
    EXPECT_EQ(kExitUsage, 2);
}

}  // namespace
}  // namespace impossible::cli
