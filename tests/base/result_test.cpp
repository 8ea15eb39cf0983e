// The one result type (base/result.hpp).
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "base/result.hpp"

namespace impossible {
namespace {

Result<int> half(int n) {
    if (n % 2) return Error{std::to_string(n) + " is odd"};
    return n / 2;
}

Result<void> check_even(int n) {
    if (n % 2) return Error{"odd"};
    return {};
}

TEST(Result, HoldsAValueOrAMessage) {
    const Result<int> good = half(8);
    ASSERT_TRUE(good);
    EXPECT_TRUE(good.has_value());
    EXPECT_EQ(*good, 4);
    const Result<int> bad = half(7);
    EXPECT_FALSE(bad);
    EXPECT_EQ(bad.error(), "7 is odd");
}

TEST(Result, VoidResultsAndMoveOnlyValues) {
    EXPECT_TRUE(check_even(2));
    EXPECT_EQ(check_even(3).error(), "odd");
    Result<std::unique_ptr<int>> owned = std::make_unique<int>(5);
    ASSERT_TRUE(owned);
    std::unique_ptr<int> taken = std::move(owned).value();
    EXPECT_EQ(*taken, 5);
    // A string value is a value, not an error.
    const Result<std::string> text = std::string("fine");
    ASSERT_TRUE(text);
    EXPECT_EQ(text->size(), 4u);
}

// A failed step passes its error on to a caller of another result type.
Result<std::string> describe_half(int n) {
    const Result<int> h = half(n);
    if (!h) return h;
    return std::to_string(*h);
}

Result<void> require_even(int n) {
    const Result<int> h = half(n);
    if (!h) return h;
    return {};
}

TEST(Result, AnErrorConvertsToAResultOfAnotherType) {
    EXPECT_EQ(*describe_half(8), "4");
    const Result<std::string> bad = describe_half(7);
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error(), "7 is odd");
    EXPECT_TRUE(require_even(4));
    EXPECT_EQ(require_even(5).error(), "5 is odd");
    const Result<int> from_void = Result<int>(check_even(3));
    ASSERT_FALSE(from_void);
    EXPECT_EQ(from_void.error(), "odd");
}

}  // namespace
}  // namespace impossible
