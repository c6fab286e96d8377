// The GLSL of callable data types (pipeline.callable_data): one struct per
// word count, one variable per location a stage calls with (numbered from 1
// inside a callable, whose location 0 is its incoming data), the last call's
// data in `callee`, and every module compiles and passes spirv-val.
#include <gtest/gtest.h>

#include "glsl/generate_glsl.h"
#include "parse_support.h"
#include "plan/plan.h"
#include "spirv/compile_glsl.h"

namespace rayspec {
namespace {

Case callDataCase() {
  return parsedCase(R"(rules: [R-CALLABLE]
scene:
  blas:
    tri: [{triangles: {vertices: [[-1, -1, 0], [1, -1, 0], [0, 1, 0]]}}]
  instances: [{blas: tri}]
rays:
  list: [{origin: [0, 0, 5], direction: [0, 0, -1]}]
pipeline:
  callable_data: [{}, {words: 6}, {words: 2}]
  raygen:
    - call: {index: 0, location: 1, word5: 50}
    - call: {index: 2, value: callee.word5}
    - record: {value: callee.value}
  callables:
    - call_data: 1
      program:
        - call: {index: 1, location: 2, word1: call.word5}
        - call_data: {word5: callee.word1}
    - {call_data: 2, program: [call_data: {word1: {mul: [call.word1, 3]}}]}
    - [call_data: {value: {add: [call.value, 1]}}]
outputs:
  per_ray: [value]
)");
}

TEST(GlslCallData, EachLocationHasItsOwnVariableAndCompiles) {
  const Case c = callDataCase();
  const GeneratedPipeline g = generateGlsl(c, derivePlan(c));
  const std::string& raygen = g.raygen.glsl;
  EXPECT_NE(raygen.find("struct RsCallDataW6 {"), std::string::npos) << raygen;
  EXPECT_NE(raygen.find("layout(location = 1) callableDataEXT RsCallDataW6 rs_callee_1;"),
            std::string::npos)
      << raygen;
  EXPECT_NE(raygen.find("layout(location = 0) callableDataEXT RsCallData rs_callee_0;"),
            std::string::npos);
  EXPECT_NE(raygen.find("RsCallDataW6 callee;"), std::string::npos);
  // The plain call's result fills the words beyond its type with zero.
  EXPECT_NE(raygen.find("callee.words[5] = 0u;"), std::string::npos);
  const std::string& callable0 = g.callables.at(0).glsl;
  EXPECT_NE(callable0.find("layout(location = 0) callableDataInEXT RsCallDataW6 call;"),
            std::string::npos)
      << callable0;
  EXPECT_NE(callable0.find("layout(location = 3) callableDataEXT RsCallDataW2 rs_callee_2;"),
            std::string::npos);
  EXPECT_NE(callable0.find("executeCallableEXT(rs_index, 3);"), std::string::npos);
  for (const GeneratedShader* s : {&g.raygen, &g.callables[0], &g.callables[1], &g.callables[2]}) {
    const SpirvResult spirv = compileGlsl(s->glsl, s->stage, s->compute);
    EXPECT_TRUE(spirv.error.empty()) << s->name << ": " << spirv.error;
  }
}

}  // namespace
}  // namespace rayspec
