// The GLSL of control flow and functions: a function is defined once, before
// main and after the functions it calls, ignore / terminate stay inside it,
// and every module compiles and passes spirv-val.
#include <gtest/gtest.h>

#include "glsl/generate_glsl.h"
#include "parse_support.h"
#include "plan/plan.h"
#include "spirv/compile_glsl.h"

namespace rayspec {
namespace {

// One triangle under one ray, with the pipeline and outputs `rest` gives.
Case triangleCase(const std::string& rest) {
  return parsedCase(
      "rules: [R-CONTROL-FLOW]\n"
      "scene:\n"
      "  blas:\n"
      "    tri: [{triangles: {vertices: [[-1, -1, 0], [1, -1, 0], [0, 1, 0]]}}]\n"
      "  instances: [{blas: tri}]\n"
      "rays:\n"
      "  list: [{origin: [0, 0, 5], direction: [0, 0, -1]}]\n"
      "pipeline:\n" +
      rest);
}

Case functionCase() {
  return triangleCase(
      "  functions:\n"
      "    inner:\n"
      "      params: {n: uint}\n"
      "      do:\n"
      "        - if: {odd: var.n}\n"
      "          then: [ignore]\n"
      "    outer:\n"
      "      params: {v: vec3}\n"
      "      do:\n"
      "        - repeat: 2\n"
      "          var: i\n"
      "          do: [{invoke: inner, with: {n: {add: [primitive_id, var.i]}}}]\n"
      "  hit_groups:\n"
      "    - any_hit:\n"
      "        - invoke: outer\n"
      "          with: {v: [1.0, 2.0, 3.0]}\n"
      "        - switch: primitive_id\n"
      "          cases: {0: [terminate]}\n"
      "      closest_hit: [record: [hit]]\n"
      "outputs:\n"
      "  per_ray: [hit]\n");
}

TEST(GlslControlFlow, FunctionsComeBeforeTheirCallersAndCompile) {
  const Case c = functionCase();
  const GeneratedPipeline g = generateGlsl(c, derivePlan(c));
  ASSERT_TRUE(g.hit_groups.at(0).any_hit);
  const std::string& glsl = g.hit_groups[0].any_hit->glsl;
  const size_t inner = glsl.find("void rs_fn_inner(uint v_n) {");
  const size_t outer = glsl.find("void rs_fn_outer(vec3 v_v) {");
  const size_t main = glsl.find("void main() {");
  ASSERT_NE(inner, std::string::npos) << glsl;
  EXPECT_LT(inner, outer);
  EXPECT_LT(outer, main);
  EXPECT_EQ(glsl.find("void rs_fn_inner", inner + 1), std::string::npos);  // once
  EXPECT_NE(glsl.find("ignoreIntersectionEXT;", inner), std::string::npos);
  EXPECT_LT(glsl.find("ignoreIntersectionEXT;", inner), outer);
  EXPECT_NE(glsl.find("rs_fn_outer(vec3(1.0, 2.0, 3.0));", main), std::string::npos);
  const SpirvResult spirv = compileGlsl(glsl, Stage::AnyHit);
  EXPECT_TRUE(spirv.error.empty()) << spirv.error;
  // The closest-hit invokes nothing: no function there.
  EXPECT_EQ(g.hit_groups[0].closest_hit->glsl.find("rs_fn_"), std::string::npos);
}

TEST(GlslControlFlow, ALoopEvaluatesItsCountOnceAndClampsIt) {
  const Case c = triangleCase(
      "  raygen:\n"
      "    - array: {name: a, of: vec2, size: 4}\n"
      "    - repeat: launch_id_x\n"
      "      var: i\n"
      "      do:\n"
      "        - store: {array: a, index: var.i, value: [1.0, 2.0]}\n"
      "        - trace: {}\n"
      "    - record: {barycentrics: {load: [var.a, 2]}}\n"
      "  hit_groups: [{closest_hit: [count: c]}]\n"
      "outputs:\n"
      "  counters: [c]\n"
      "  per_ray: [barycentrics]\n");
  const GeneratedPipeline g = generateGlsl(c, derivePlan(c));
  const std::string& glsl = g.raygen.glsl;
  EXPECT_NE(glsl.find("vec2 v_a[4];"), std::string::npos) << glsl;
  EXPECT_NE(glsl.find("min(RS_LAUNCH_ID.x, 1024u)"), std::string::npos);
  EXPECT_NE(glsl.find("v_a[(2u) % uint(v_a.length())]"), std::string::npos);
  const SpirvResult spirv = compileGlsl(glsl, Stage::Raygen);
  EXPECT_TRUE(spirv.error.empty()) << spirv.error;
}

// A sized array is declared with a null initialiser (OpConstantNull), the
// extensions its types need enabled once each; sized vectors compile.
TEST(GlslControlFlow, SizedArraysAreNullInitialisedAndCompile) {
  const Case c = triangleCase(
      "  raygen:\n"
      "    - array: {name: a, of: i16vec3, size: 5}\n"
      "    - array: {name: b, of: int8, size: 2}\n"
      "    - store: {array: a, index: 1, value: {i16vec3: [1, 2, {int16: launch_id_x}]}}\n"
      "    - trace: {}\n"
      "    - record: {value: {uint: {add: [{z: {load: [var.a, 1]}}, {int16: {load: [var.b, "
      "0]}}]}}}\n"
      "  hit_groups: [{closest_hit: [count: c]}]\n"
      "outputs:\n"
      "  counters: [c]\n"
      "  per_ray: [value]\n");
  const GeneratedPipeline g = generateGlsl(c, derivePlan(c));
  const std::string& glsl = g.raygen.glsl;
  EXPECT_NE(glsl.find("i16vec3 v_a[5] = {};"), std::string::npos) << glsl;
  EXPECT_NE(glsl.find("int8_t v_b[2] = {};"), std::string::npos);
  EXPECT_NE(glsl.find("#extension GL_EXT_null_initializer : require"), std::string::npos);
  const size_t int16 = glsl.find("#extension GL_EXT_shader_explicit_arithmetic_types_int16");
  ASSERT_NE(int16, std::string::npos);
  EXPECT_EQ(glsl.find("#extension GL_EXT_shader_explicit_arithmetic_types_int16", int16 + 1),
            std::string::npos);
  const SpirvResult spirv = compileGlsl(glsl, Stage::Raygen);
  EXPECT_TRUE(spirv.error.empty()) << spirv.error;
}

// int32 vectors are core GLSL's ivec: no #extension line of their own
// (only the null initialiser's), and they compile.
TEST(GlslControlFlow, Int32VectorsAreCoreIvec) {
  const Case c = triangleCase(
      "  raygen:\n"
      "    - array: {name: a, of: ivec3, size: 2}\n"
      "    - store: {array: a, index: 1, value: {ivec3: [1, 2, {int32: launch_id_x}]}}\n"
      "    - trace: {}\n"
      "    - record: {value: {uint: {sub: [{z: {load: [var.a, 1]}}, 2000000000]}}}\n"
      "  hit_groups: [{closest_hit: [count: c]}]\n"
      "outputs:\n"
      "  counters: [c]\n"
      "  per_ray: [value]\n");
  const GeneratedPipeline g = generateGlsl(c, derivePlan(c));
  const std::string& glsl = g.raygen.glsl;
  EXPECT_NE(glsl.find("ivec3 v_a[2] = {};"), std::string::npos) << glsl;
  EXPECT_NE(glsl.find("int(2000000000u)"), std::string::npos) << glsl;
  EXPECT_EQ(glsl.find("explicit_arithmetic"), std::string::npos) << glsl;
  EXPECT_EQ(glsl.find("#extension  "), std::string::npos) << glsl;
  const SpirvResult spirv = compileGlsl(glsl, Stage::Raygen);
  EXPECT_TRUE(spirv.error.empty()) << spirv.error;
}

// A struct local is one GLSL struct, its type defined once at file scope
// for each distinct member list (in every stage), its members prefixed
// (a member may be named as a GLSL keyword); it compiles.
TEST(GlslControlFlow, StructTypesAreDefinedOnceAndCompile) {
  const Case c = triangleCase(
      "  raygen:\n"
      "    - struct: {name: s, members: {in: int8, b: f16vec2, c: ivec3}}\n"
      "    - struct: {name: t, members: {in: int8, b: f16vec2, c: ivec3}}\n"
      "    - set: {s.in: {int8: launch_id_x}, t.c: {ivec3: 7}}\n"
      "    - trace: {}\n"
      "    - record: {value: {add: [{uint: var.s.in}, {uint: {z: var.t.c}}]}}\n"
      "  hit_groups: [{closest_hit: [{struct: {name: s, members: {x: float64}}}]}]\n"
      "outputs:\n"
      "  per_ray: [value]\n");
  const GeneratedPipeline g = generateGlsl(c, derivePlan(c));
  const std::string& glsl = g.raygen.glsl;
  const std::string type = "RsStruct_int8_in_f16vec2_b_ivec3_c";
  const size_t defined = glsl.find("struct " + type + " {");
  ASSERT_NE(defined, std::string::npos) << glsl;
  EXPECT_EQ(glsl.find("struct " + type + " {", defined + 1), std::string::npos);
  EXPECT_NE(glsl.find("int8_t m_in;"), std::string::npos) << glsl;
  EXPECT_NE(glsl.find(type + " v_s = " + type + "(int8_t(0), f16vec2(0), ivec3(0));"),
            std::string::npos)
      << glsl;
  EXPECT_NE(glsl.find("v_s.m_in = "), std::string::npos);
  EXPECT_NE(glsl.find("struct RsStruct_float64_x {"), std::string::npos);  // the hit group's
  ASSERT_TRUE(g.hit_groups[0].closest_hit.has_value());
  EXPECT_NE(g.hit_groups[0].closest_hit->glsl.find("RsStruct_float64_x v_s"), std::string::npos);
  const SpirvResult spirv = compileGlsl(glsl, Stage::Raygen);
  EXPECT_TRUE(spirv.error.empty()) << spirv.error;
}

// Each shader gets the values pipeline.specialize sets for it, as 32-bit
// words by constant_id; every stage declares every constant with its default.
TEST(GlslControlFlow, SpecializationReachesEachShader) {
  const Case c = triangleCase(
      "  constants: {n: 2, scale: 0.5, on: false}\n"
      "  specialize: {raygen: {scale: 2, on: true}, miss0: {n: 7}}\n"
      "  raygen: [trace: {}, {if: const.on, then: [{record: {ray_tmin: const.scale}}]}]\n"
      "  miss: [[payload: {value: const.n}]]\n"
      "  hit_groups: [{closest_hit: [payload: {value: 1}]}]\n"
      "outputs:\n"
      "  per_ray: [ray_tmin]\n");
  const GeneratedPipeline g = generateGlsl(c, derivePlan(c));
  using Pairs = std::vector<std::pair<uint32_t, uint32_t>>;
  EXPECT_EQ(g.raygen.specialization, (Pairs{{1, 0x40000000u}, {2, 1u}}));
  EXPECT_EQ(g.miss.at(0).specialization, (Pairs{{0, 7u}}));
  EXPECT_TRUE(g.hit_groups.at(0).closest_hit->specialization.empty());
  EXPECT_NE(g.raygen.glsl.find("layout(constant_id = 1) const float c_scale = 0.5;"),
            std::string::npos)
      << g.raygen.glsl;
  EXPECT_NE(g.miss[0].glsl.find("payload.value = c_n;"), std::string::npos);
  const SpirvResult spirv = compileGlsl(g.raygen.glsl, Stage::Raygen);
  EXPECT_TRUE(spirv.error.empty()) << spirv.error;
}

}  // namespace
}  // namespace rayspec
