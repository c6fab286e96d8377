// pipeline.traces (case/parse_pipeline.cpp, case/ray_query_inlining.h): a
// case may ask to trace by ray queries; a value that is neither form, or a
// case its ray query form cannot express, is an error at the field.
#include <gtest/gtest.h>

#include <string>

#include "case/parse_case.h"
#include "case_support.h"

namespace rayspec {
namespace {

// A triangle and a box; `traces` on line 9, `closest_hit` the group's program.
std::string tracesCase(const std::string& traces,
                       const std::string& closest_hit = "[record: [hit]]") {
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
         "  max_recursion: 2\n"
         "  miss: [[record: {hit: 0}]]\n"
         "  hit_groups: [{closest_hit: " +
         closest_hit +
         "}]\n"
         "outputs:\n"
         "  per_ray: [hit]\n";
}

TEST(RayQueryCase, TracesTakesEitherForm) {
  EXPECT_TRUE(parsedCase(tracesCase("ray_query")).pipeline.ray_query);
  EXPECT_FALSE(parsedCase(tracesCase("trace_ray")).pipeline.ray_query);
  expectError(parse(tracesCase("inline")), 9, "pipeline.traces", "must be trace_ray, ray_query");
}

TEST(RayQueryCase, WhatTheFormCannotExpressIsAnErrorAtTheField) {
  const std::string nested = "[trace: {origin: [0, 0, 1], direction: [0, 0, -1]}]";
  expectError(parse(tracesCase("ray_query", nested)), 9, "pipeline.traces",
              "closest-hit or miss traces");
  const ParseResult plain = parse(tracesCase("trace_ray", nested));
  EXPECT_TRUE(plain.value.has_value()) << allErrors(plain);
}

}  // namespace
}  // namespace rayspec
