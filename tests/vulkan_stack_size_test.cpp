// The pipeline stack size a case sets (pipeline.callable_depth, R-STACK):
// the specification's formula with the case's callable frames, and the
// field's parse errors. The device side runs in callable/stack-depth.
#include <gtest/gtest.h>

#include "parse/parse_case.h"
#include "vulkan/stack_size.h"

namespace rayspec {
namespace {

ShaderStackSizes sizes() {
  ShaderStackSizes s;
  s.raygen = 100;
  s.miss = 30;
  s.closest_hit = 50;
  s.any_hit = 20;
  s.intersection = 40;
  s.callable = 7;
  return s;
}

TEST(StackSize, DefaultDepthIsTheSpecificationsFormula) {
  // 100 + 1 x max(50, 30, 40 + 20) + 0 x max(50, 30) + 2 x 7
  EXPECT_EQ(pipelineStackSize(sizes(), 1, 2), 100u + 60u + 14u);
}

TEST(StackSize, EveryCallableFrameAndNestedTraceAddsItsStack) {
  // 100 + 60 + 2 x 50 + 5 x 7
  EXPECT_EQ(pipelineStackSize(sizes(), 3, 5), 100u + 60u + 100u + 35u);
  EXPECT_EQ(pipelineStackSize(sizes(), 3, 6) - pipelineStackSize(sizes(), 3, 5), 7u);
}

TEST(StackSize, NoTracesCountOnlyRaygenAndCallables) {
  EXPECT_EQ(pipelineStackSize(sizes(), 0, 3), 100u + 21u);
}

TEST(StackSize, CallableDepthParsesAndIsChecked) {
  auto parse = [](const std::string& depth) {
    return parseCaseText(
        "rules: [R-STACK]\nrays:\n  list: [{origin: [0, 0, 1], direction: [0, 0, "
        "-1]}]\npipeline:\n  callable_depth: " +
            depth + "\n  miss: [[count: miss]]\noutputs:\n  counters: [miss]\n",
        "t.yaml", "t/t");
  };
  const ParseResult ok = parse("5");
  ASSERT_TRUE(ok.value) << (ok.errors.empty() ? "" : ok.errors[0].format());
  EXPECT_EQ(ok.value->pipeline.callableDepth(), 5u);
  for (const std::string bad : {"0", "17", "two"}) {
    const ParseResult r = parse(bad);
    ASSERT_FALSE(r.errors.empty()) << bad;
    EXPECT_NE(r.errors[0].format().find("t.yaml:5"), std::string::npos) << r.errors[0].format();
    EXPECT_NE(r.errors[0].format().find("pipeline.callable_depth"), std::string::npos)
        << r.errors[0].format();
  }
}

}  // namespace
}  // namespace rayspec
