// pipeline.traces: ray_query_compute (parse/parse_pipeline.cpp,
// case/ray_query_inlining.h): raygen and its ray query loops run as a compute
// shader; what a compute shader cannot do is an error at the field.
#include <gtest/gtest.h>

#include <string>

#include "case/ray_query_inlining.h"
#include "parse/parse_case.h"
#include "parse_support.h"

namespace rayspec {
namespace {

// A triangle; `traces` on line 9, `raygen` raygen's program, one callable.
std::string computeTracesCase(const std::string& traces, const std::string& raygen) {
  return "rules: [R-RQ-EQUIV]\n"
         "scene:\n"
         "  blas:\n"
         "    t: [{triangles: {vertices: [[-1, -1, 0], [1, -1, 0], [-1, 1, 0]]}}]\n"
         "  instances: [{blas: t}]\n"
         "rays:\n"
         "  list: [{origin: [0, 0, 1], direction: [0, 0, -1]}]\n"
         "pipeline:\n"
         "  traces: " +
         traces +
         "\n"
         "  raygen: " +
         raygen +
         "\n"
         "  miss: [[record: {hit: 0}]]\n"
         "  hit_groups: [{closest_hit: [record: [hit]]}]\n"
         "  callables: [[record: {value: 3}]]\n"
         "outputs:\n"
         "  per_ray: [hit, value]\n";
}

TEST(ComputeTracesCase, RayQueryComputeIsARayQueryFormRunFromCompute) {
  const Case c = parsedCase(computeTracesCase("ray_query_compute", "[trace: {}]"));
  EXPECT_TRUE(c.pipeline.ray_query);
  EXPECT_TRUE(c.pipeline.from_compute);
  EXPECT_FALSE(parsedCase(computeTracesCase("ray_query", "[trace: {}]")).pipeline.from_compute);
}

TEST(ComputeTracesCase, ACallableIsAnErrorAtTheFieldFromComputeOnly) {
  const std::string calls = "[trace: {}, call: {index: 0}]";
  expectError(parse(computeTracesCase("ray_query_compute", calls)), 9, "pipeline.traces",
              "executeCallableEXT has no compute form");
  const ParseResult in_raygen = parse(computeTracesCase("ray_query", calls));
  EXPECT_TRUE(in_raygen.value.has_value()) << allErrors(in_raygen);
  // --through ray-query-compute says the same of the plain case.
  const Case plain = parsedCase(computeTracesCase("trace_ray", calls));
  EXPECT_NE(computeRayQueryObstacle(plain).find("executeCallableEXT"), std::string::npos);
  EXPECT_EQ(rayQueryObstacle(plain), "");
}

}  // namespace
}  // namespace rayspec
