// pipeline.traces (parse/parse_pipeline.cpp, case/ray_query_inlining.h): a
// case may ask to trace by ray queries; a value that is neither form, or a
// case its ray query form cannot express, is an error at the field.
#include <gtest/gtest.h>

#include <string>

#include "parse/parse_case.h"
#include "parse_support.h"

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
  expectError(parse(tracesCase("inline")), 9, "pipeline.traces",
              "trace_ray, ray_query, ray_query_compute or ray_query_in_hit");
}

// A closest-hit that traces: nested queries in raygen, or the closest-hit's
// own queries; the in-hit form needs such a trace.
TEST(RayQueryCase, NestedTracesTakeBothQueryForms) {
  const std::string nested = "[trace: {origin: [0, 0, 1], direction: [0, 0, -1]}]";
  EXPECT_TRUE(parsedCase(tracesCase("ray_query", nested)).pipeline.ray_query);
  const Case in_hit = parsedCase(tracesCase("ray_query_in_hit", nested));
  EXPECT_TRUE(in_hit.pipeline.ray_query_in_hit);
  EXPECT_FALSE(in_hit.pipeline.ray_query);
  expectError(parse(tracesCase("ray_query_in_hit")), 9, "pipeline.traces",
              "ray_query_in_hit cannot express this case: no closest-hit or miss traces");
}

// Two trace sites in closest-hit over 31 levels would inline 2^31 copies.
TEST(RayQueryCase, TooManyInlinedCopiesIsAnErrorAtTheField) {
  std::string text = tracesCase("ray_query",
                                "[trace: {origin: [0, 0, 1], direction: [0, 0, -1]}, "
                                "trace: {origin: [0, 0, 2], direction: [0, 0, -1]}]");
  text.replace(text.find("max_recursion: 2"), 16, "max_recursion: 31");
  expectError(parse(text), 9, "pipeline.traces", "more than 64 copies");
}

}  // namespace
}  // namespace rayspec
