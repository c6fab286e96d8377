// pipeline.tlas_function: whether every trace and query passes its top level
// through a function (glsl/tlas_function.h); anything but true or false is
// an error at its line and field.
#include <gtest/gtest.h>

#include "parse/parse_case.h"
#include "parse_support.h"

namespace rayspec {
namespace {

std::string withTlasFunction(const std::string& value) {
  std::string text = oneTriangleText("R-PAYLOAD", "", "");
  text.replace(text.find("pipeline:\n"), 10, "pipeline:\n  tlas_function: " + value + "\n");
  return text;
}

TEST(TlasFunction, IsReadAndDefaultsToFalse) {
  EXPECT_FALSE(parsedCase(oneTriangleText("R-PAYLOAD", "", "")).pipeline.tlas_function);
  EXPECT_TRUE(parsedCase(withTlasFunction("true")).pipeline.tlas_function);
  EXPECT_FALSE(parsedCase(withTlasFunction("false")).pipeline.tlas_function);
}

TEST(TlasFunction, AnythingElseIsAnErrorAtItsLine) {
  expectError(parse(withTlasFunction("sometimes")), 9, "pipeline.tlas_function", "true or false");
}

}  // namespace
}  // namespace rayspec
