// Helpers of the case reader's tests (parse_test.cpp and its topics): parse a
// case text, show its errors, expect one error at a line and field, and a good
// case to start from.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "parse/parse_case.h"

namespace rayspec {

inline ParseResult parse(const std::string& text) {
  return parseCaseText(text, "t.yaml", "family/t");
}

inline std::string allErrors(const ParseResult& r) {
  std::string s;
  for (const Error& e : r.errors) s += e.format() + "\n";
  return s;
}

// The first error, formatted, or "(no error)".
inline std::string firstError(const ParseResult& r) {
  return r.errors.empty() ? std::string("(no error)") : r.errors[0].format();
}

// A case of one triangle and one ray that hits it, for the tests of one
// scene field: `build` is scene.build's value ("" for none) and
// `triangle_extra` more fields of the triangles' map ("" for none).
inline std::string oneTriangleText(const std::string& rule, const std::string& build,
                                   const std::string& triangle_extra) {
  return "rules: [" + rule + "]\n" + "scene:\n" +
         (build.empty() ? std::string() : "  build: " + build + "\n") +
         "  blas:\n"
         "    t: [{triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]" +
         (triangle_extra.empty() ? std::string() : ", " + triangle_extra) +
         "}}]\n"
         "  instances: [{blas: t}]\n"
         "rays:\n"
         "  list: [{origin: [0.2, 0.2, 1], direction: [0, 0, -1]}]\n"
         "pipeline:\n"
         "  hit_groups: [{closest_hit: [record: [hit]]}]\n"
         "outputs:\n"
         "  per_ray: [hit]\n";
}

// The case a text holds; a parse error fails the test (and gives an empty case).
inline Case parsedCase(const std::string& text) {
  const ParseResult r = parse(text);
  EXPECT_TRUE(r.value.has_value()) << allErrors(r);
  return r.value ? *r.value : Case{};
}

// Expects an error on `line` whose field contains `field` and message contains `text`.
inline void expectError(const ParseResult& r, int line, const std::string& field,
                        const std::string& text = "") {
  EXPECT_FALSE(r.value.has_value());
  for (const Error& e : r.errors)
    if (e.loc.line == line && e.loc.field.find(field) != std::string::npos &&
        e.message.find(text) != std::string::npos)
      return;
  ADD_FAILURE() << "no error at line " << line << " field " << field << " (" << text << "); got:\n"
                << allErrors(r);
}

inline const char* const kGood = R"(rules: [R-IGNORE, R-MISS-XOR-CHIT]
description: a quad and an inactive instance
scene:
  blas:
    quad:
      - triangles:
          vertices: [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]]
          indices: [0, 1, 2, 0, 2, 3]
        flags: [opaque, no_duplicate_any_hit]
    balls:
      - aabbs: [[-1, -1, -1, 1, 1, 1], [.nan, 0, 0, 1, 1, 1]]
  instances:
    - blas: quad
      transform: {translate: [1, 2, 3], scale: 2, rotate: {axis: [0, 0, 1], degrees: 90}}
      mask: 0x0F
      custom_index: 7
      sbt_offset: 1
      flags: [triangle_flip_facing, force_opaque]
    - blas: null
    - blas: balls
      transform: [1, 0, 0, 5, 0, 1, 0, 0, 0, 0, 1, 0]
rays:
  camera: {size: [2, 2], origin: [0, 0, 5], look_at: [0, 0, 0], up: [0, 1, 0], fov: 90}
  tmin: 0.001
  tmax: 100
  flags: [cull_back_facing, skip_aabbs]
  cull_mask: 0x1FF
pipeline:
  miss:
    - [count: miss, record: {hit: 0}]
  hit_groups:
    - closest_hit: [count: closesthit, record: [primitive_id, hit_t]]
    - any_hit:
        - if: {odd: primitive_id}
          then: [ignore]
      intersection:
        - if: sphere_hit
          then:
            - report: {t: sphere_near, kind: 3, accepted: [count: reported]}
outputs:
  counters: [miss, closesthit, reported]
  per_ray: [hit, primitive_id, hit_t]
  images:
    - {name: primitive, from: primitive_id}
)";

}  // namespace rayspec
