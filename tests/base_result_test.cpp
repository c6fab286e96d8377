// base/result.h's propagation macros and base/error.h's kinds: a failed step
// returns its error unchanged (kind and failed call included), a good one
// hands its value on.
#include <gtest/gtest.h>

#include <string>

#include "base/result.h"

namespace rayspec {
namespace {

Result<int> halfOfEven(int n) {
  if (n % 2) return errorOf(ErrorKind::Input, std::to_string(n) + " is odd");
  return n / 2;
}

Result<void> failingDeviceCall() {
  Error e = errorOf(ErrorKind::Device, "vkQueueSubmit: VK_ERROR_DEVICE_LOST");
  e.call = "vkQueueSubmit";
  e.result = "VK_ERROR_DEVICE_LOST";
  return e;
}

// Two halvings in a row, then a step that may fail with nothing to return.
Result<int> quarterThen(int n, bool fail) {
  RAYSPEC_TRY(const int half, halfOfEven(n));
  int quarter = 0;
  RAYSPEC_TRY(quarter, halfOfEven(half));
  if (fail) RAYSPEC_TRY_VOID(failingDeviceCall());
  return quarter;
}

TEST(ResultTry, GoodStepsHandTheirValuesOn) {
  const Result<int> q = quarterThen(12, false);
  ASSERT_TRUE(q);
  EXPECT_EQ(*q, 3);
}

TEST(ResultTry, TheFirstFailedStepIsTheError) {
  const Result<int> first = quarterThen(7, false);
  ASSERT_FALSE(first);
  EXPECT_EQ(first.error().message, "7 is odd");
  const Result<int> second = quarterThen(6, false);
  ASSERT_FALSE(second);
  EXPECT_EQ(second.error().message, "3 is odd");
}

TEST(ResultTry, AnErrorKeepsItsKindAndFailedCall) {
  const Result<int> lost = quarterThen(8, true);
  ASSERT_FALSE(lost);
  EXPECT_EQ(lost.error().kind, ErrorKind::Device);
  EXPECT_EQ(lost.error().call, "vkQueueSubmit");
  EXPECT_EQ(lost.error().result, "VK_ERROR_DEVICE_LOST");
  EXPECT_EQ(errorMessage("x").kind, ErrorKind::Input);
}

TEST(ResultTry, ContextPrecedesTheMessageAndKeepsTheKind) {
  Error e = errorOf(ErrorKind::Harness, "no results.json");
  e.loc.file = "out/a/model/results.json";
  e.loc.line = 3;
  e.loc.column = 1;
  const Error c = withContext("model side: ", e);
  EXPECT_EQ(c.kind, ErrorKind::Harness);
  EXPECT_TRUE(c.loc.file.empty());
  EXPECT_EQ(c.format(), "model side: out/a/model/results.json:3:1: no results.json");
}

}  // namespace
}  // namespace rayspec
