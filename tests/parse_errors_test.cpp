// The case reader's errors: each names the line and field, and mangled input
// never crashes it.
#include <gtest/gtest.h>

#include <string>

#include "parse/parse_case.h"
#include "parse_support.h"

namespace rayspec {
namespace {

// ---- errors: line and field ----

TEST(ParseCaseErrors, UnknownTraceCommand) {
  const std::string text = R"(rules: [R-MASK]
scene:
  instances: []
rays:
  list: [{origin: [0, 0, 1], direction: [0, 0, -1]}]
  command: indirect3
)";
  ParseResult r = parse(text);
  expectError(r, 6, "rays.command", "unknown trace command 'indirect3'");
}

TEST(ParseCaseErrors, UnknownKey) {
  const std::string text = R"(rules: [R-MASK]
scene:
  instancess: []
rays:
  list: [{origin: [0, 0, 1], direction: [0, 0, -1], tmaxx: 3}]
)";
  ParseResult r = parse(text);
  expectError(r, 3, "scene.instancess", "unknown key");
  expectError(r, 5, "rays.list[0].tmaxx", "unknown key");
  EXPECT_EQ(r.errors.size(), 2u) << allErrors(r);
  EXPECT_EQ(r.errors[0].format(),
            "t.yaml:3:3: scene.instancess: unknown key 'instancess' (expected one of: blas, "
            "instances, build, update, split)");
}

const char* kScene = R"(rules: [R-MASK]
scene:
  blas:
    quad:
      - triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}
  instances:
    - blas: quad
      mask: @MASK@
      custom_index: @CUSTOM@
    - blas: @BLAS@
rays:
  list: [{origin: [0, 0, 1], direction: [0, 0, -1]}]
pipeline: {miss: [[]], hit_groups: [{}]}
)";

std::string sceneWith(const std::string& mask, const std::string& custom, const std::string& blas) {
  std::string s = kScene;
  s.replace(s.find("@MASK@"), 6, mask);
  s.replace(s.find("@CUSTOM@"), 8, custom);
  s.replace(s.find("@BLAS@"), 6, blas);
  return s;
}

TEST(ParseCaseErrors, BitWidths) {
  EXPECT_TRUE(parse(sceneWith("0xFF", "0xFFFFFF", "quad")).value);
  ParseResult r = parse(sceneWith("0x1FF", "0x1000000", "quad"));
  expectError(r, 8, "scene.instances[0].mask", "out of range");
  expectError(r, 9, "scene.instances[0].custom_index", "out of range");
  r = parse(sceneWith("-1", "0", "quad"));
  expectError(r, 8, "scene.instances[0].mask", "unsigned integer");
}

TEST(ParseCaseErrors, UnknownBlas) {
  ParseResult r = parse(sceneWith("1", "0", "sphere"));
  expectError(r, 10, "scene.instances[1].blas", "unknown BLAS 'sphere'");
}

TEST(ParseCaseErrors, MixedBlasAndBadGeometry) {
  const std::string text = R"(rules: [R-MASK]
scene:
  blas:
    mixed:
      - triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]], indices: [0, 1, 3]}
      - aabbs: [[0, 0, 0, 1, 1, 1]]
      - aabbs: [[0, 0, 0, -1, 1, 1]]
      - triangles: {vertices: [[0, 0, 0], [1, 0, 0]]}
rays:
  list: [{origin: [0, 0, 1], direction: [0, 0, -1]}]
)";
  ParseResult r = parse(text);
  expectError(r, 5, "scene.blas.mixed[0].triangles.indices[2]", "past the last vertex");
  expectError(r, 6, "scene.blas.mixed[1]", "only triangles or only aabbs");
  expectError(r, 7, "scene.blas.mixed[2].aabbs[0]", "min is greater than max");
  expectError(r, 8, "scene.blas.mixed[3].triangles.vertices", "multiple of 3");
}

const char* kProgramCase = R"(rules: [R-IGNORE]
rays:
  list: [{origin: [0, 0, 1], direction: [0, 0, -1]}]
pipeline:
  miss:
    - [count: miss]
  hit_groups:
    - closest_hit:
        - count: closesthit
        - BODY
outputs:
  counters: [closesthit]
  per_ray: [hit, primitive_id]
)";

ParseResult programCase(const std::string& body) {
  std::string s = kProgramCase;
  s.replace(s.find("BODY"), 4, body);
  return parse(s);
}

TEST(ParseCaseErrors, UndeclaredCounter) {
  ParseResult r = programCase("record: [primitive_id]");
  expectError(r, 6, "pipeline.miss[0][0].count", "'miss' is not declared in outputs.counters");
}

TEST(ParseCaseErrors, IgnoreInClosestHit) {
  std::string s = kProgramCase;
  s.replace(s.find("[count: miss]"), 13, "[]");
  s.replace(s.find("BODY"), 4, "ignore");
  ParseResult r = parse(s);
  ASSERT_EQ(r.errors.size(), 1u) << allErrors(r);
  expectError(r, 10, "pipeline.hit_groups[0].closest_hit[1]",
              "'ignore' is not allowed in closest_hit");
}

TEST(ParseCaseErrors, TypeErrorInOp) {
  std::string s = kProgramCase;
  s.replace(s.find("[count: miss]"), 13, "[]");
  s.replace(s.find("BODY"), 4,
            "if: {and: [{odd: hit_t}, true]}\n          then: [count: closesthit]");
  ParseResult r = parse(s);
  ASSERT_EQ(r.errors.size(), 1u) << allErrors(r);
  expectError(r, 10, "pipeline.hit_groups[0].closest_hit[1].if.and[0]", "need Uint");
  EXPECT_EQ(r.errors[0].loc.column, 22);
}

TEST(ParseCaseErrors, RecordChecks) {
  std::string s = kProgramCase;
  s.replace(s.find("[count: miss]"), 13, "[]");
  std::string a = s, b = s, c = s, d = s;
  a.replace(a.find("BODY"), 4, "record: [hit_t]");  // not declared
  expectError(parse(a), 10, "closest_hit[1].record.hit_t", "not declared in outputs.per_ray");
  b.replace(b.find("BODY"), 4, "record: [value]");  // no built-in named value
  expectError(parse(b), 10, "closest_hit[1].record[0]", "needs a built-in named 'value'");
  c.replace(c.find("BODY"), 4, "record: {primitive_id: hit_t}");
  expectError(parse(c), 10, "closest_hit[1].record.primitive_id",
              "the judge reads it as the hit itself");
  d.replace(d.find("BODY"), 4, "frobnicate: 1");
  expectError(parse(d), 10, "closest_hit[1].frobnicate", "unknown statement");
}

TEST(ParseCaseErrors, NestedTraceNeedsRecursion) {
  std::string s = kProgramCase;
  s.replace(s.find("[count: miss]"), 13, "[]");
  s.replace(s.find("BODY"), 4, "trace: {origin: hit_position, direction: [0, 0, 1]}");
  expectError(parse(s), 10, "closest_hit[1].trace", "max_recursion >= 2");
}

// The payload a trace starts with: color and value only, typed as the payload's.
TEST(ParseCaseErrors, TraceStartPayload) {
  std::string s = kProgramCase;
  s.replace(s.find("[count: miss]"), 13, "[]");
  std::string a = s, b = s;
  a.replace(a.find("BODY"), 4,
            "trace: {origin: hit_position, direction: [0, 0, 1], payload: {depth: 1}}");
  expectError(parse(a), 10, "closest_hit[1].trace.payload", "depth");
  b.replace(b.find("BODY"), 4,
            "trace: {origin: hit_position, direction: [0, 0, 1], payload: {value: hit_t}}");
  expectError(parse(b), 10, "closest_hit[1].trace.payload.value", "expected Uint, got Float");
}

// pipeline.libraries: each group in range and in at most one library, no
// empty library.
TEST(ParseCaseErrors, PipelineLibraries) {
  const std::string base = R"(rules: [R-LIBRARY]
rays:
  list: [{origin: [0, 0, 1], direction: [0, 0, -1]}]
pipeline:
  miss: [[], []]
  hit_groups: [{closest_hit: []}]
  libraries: @LIBS@
)";
  auto with = [&](const std::string& libs) {
    std::string s = base;
    s.replace(s.find("@LIBS@"), 6, libs);
    return parse(s);
  };
  ParseResult ok = with("[{miss: [1], libraries: [{hit_groups: [0]}]}]");
  ASSERT_TRUE(ok.value) << allErrors(ok);
  ASSERT_EQ(ok.value->pipeline.libraries.size(), 1u);
  EXPECT_EQ(ok.value->pipeline.libraries[0].miss, std::vector<uint32_t>{1});
  EXPECT_EQ(ok.value->pipeline.libraries[0].libraries[0].hit_groups, std::vector<uint32_t>{0});
  expectError(with("[{miss: [2]}]"), 7, "pipeline.libraries[0].miss[0]",
              "pipeline.miss has 2 entries, no 2");
  expectError(with("[{miss: [1]}, {miss: [1]}]"), 7, "pipeline.libraries[1].miss[0]",
              "already in a library");
  expectError(with("[{}]"), 7, "pipeline.libraries[0]", "at least one group or library");
  expectError(with("[{raygen: true}]"), 7, "pipeline.libraries[0].raygen", "");
}

// pipeline.raygens / raygen_group, and flags written as numbers.
TEST(ParseCaseErrors, RaygenGroupsAndRawFlags) {
  const std::string base = R"(rules: [R-RAYGEN-REGION]
scene:
  blas:
    t:
      - triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}
  instances: [{blas: t, flags: @FLAGS@}]
rays:
  list: [{origin: [0, 0, 1], direction: [0, 0, -1]}]
pipeline:
  @RAYGEN@
  hit_groups: [{closest_hit: []}]
)";
  auto with = [&](const std::string& flags, const std::string& raygen) {
    std::string s = base;
    s.replace(s.find("@FLAGS@"), 7, flags);
    s.replace(s.find("@RAYGEN@"), 8, raygen);
    return parse(s);
  };
  ParseResult ok =
      with("[1, force_opaque]", "raygens: [[trace: {}], [count: x]]\n  raygen_group: 0");
  EXPECT_FALSE(ok.value) << "the other raygen is type-checked too: x is no declared counter";
  ok = with("[1, force_opaque]", "raygens: [[], [trace: {}], []]\n  raygen_group: 1");
  ASSERT_TRUE(ok.value) << allErrors(ok);
  EXPECT_EQ(ok.value->scene.instances[0].flags, kInstanceFacingCullDisable | kInstanceForceOpaque);
  EXPECT_EQ(ok.value->pipeline.raygen_group, 1u);
  EXPECT_EQ(ok.value->pipeline.raygenGroupCount(), 3u);
  EXPECT_EQ(ok.value->pipeline.raygen.size(), 1u);
  expectError(with("[0x40]", "raygens: [[trace: {}]]"), 6, "scene.instances[0].flags[0]",
              "bits 0x40 of 64 are no known flag");
  expectError(with("[]", "raygens: [[trace: {}]]\n  raygen_group: 1"), 11, "pipeline.raygen_group",
              "");
  expectError(with("[]", "raygen: [trace: {}]\n  raygen_group: 0"), 11, "pipeline.raygen_group",
              "needs pipeline.raygens");
}

TEST(ParseCaseErrors, SbtIndexOutOfRange) {
  const std::string text = R"(rules: [R-SBT-MISS]
rays:
  list: [{origin: [0, 0, 1], direction: [0, 0, -1]}]
pipeline:
  miss: [[]]
  sbt:
    miss: [0, 1]
    hit: [{group: 0, data: {uints: [1, 2, 3, 4, 5, 6, 7, 8, 9]}}]
)";
  ParseResult r = parse(text);
  expectError(r, 7, "pipeline.sbt.miss[1]", "no miss shader 1");
  expectError(r, 8, "pipeline.sbt.hit[0].data.uints", "at most 8 words");
  expectError(r, 8, "pipeline.sbt.hit[0].group", "no hit group 0");
}

TEST(ParseCaseErrors, MissingAndMisc) {
  ParseResult r = parse("description: no rules, no rays\n");
  expectError(r, 1, "rules", "missing");
  expectError(r, 1, "rays", "missing");
  r = parse("rules: [not-a-rule]\nrays: {list: [{origin: [0, 0, 1], direction: [0, 0, -1]}]}\n");
  expectError(r, 1, "rules[0]", "not a rule label");
  r = parse(
      "rules: [R-MASK]\nrays: {camera: {size: [2, 2], origin: [0, 0, 0], look_at: [0, 0, 0], fov: "
      "40}}\n");
  expectError(r, 2, "rays.camera", "degenerate");
  r = parse(
      "rules: [R-MASK]\nrays: {list: [{origin: [0, 0, 1], direction: [0, 0, -1]}], grid: {}}\n");
  expectError(r, 2, "rays", "exactly one of camera, grid, list, aim or same");
  r = parse(
      "rules: [R-MASK]\nrays: {list: [{origin: [0, 0, 1], direction: [0, 0, -1]}]}\noutputs: "
      "{per_ray: [miss_runs, colour], images: [{name: x, from: hit}]}\n");
  expectError(r, 3, "outputs.per_ray[0]", "automatic");
  expectError(r, 3, "outputs.per_ray[1]", "unknown per-ray field");
  expectError(r, 3, "outputs.images[0].from", "not declared");
}

TEST(ParseCaseErrors, MalformedYaml) {
  ParseResult r = parse("rules: [R-MASK\nscene: {}\nrays: x\n");
  ASSERT_FALSE(r.errors.empty());
  EXPECT_FALSE(r.value);
  EXPECT_GE(r.errors[0].loc.line, 1);
  EXPECT_LE(r.errors[0].loc.line, 3);
  EXPECT_NE(r.errors[0].format().find("t.yaml:"), std::string::npos);
  r = parse("rules: [R-MASK]\nrays:\n  list: [\n   - {origin\n");
  ASSERT_FALSE(r.errors.empty());
  r = parse("");
  ASSERT_FALSE(r.errors.empty());
  r = parse("- just\n- a list\n");
  ASSERT_FALSE(r.errors.empty());
}

// Every prefix and every single-line deletion of a good case must parse or
// fail cleanly: never crash, never throw.
TEST(ParseCaseErrors, NeverCrashesOnMangledInput) {
  const std::string good = kGood;
  std::vector<std::string> lines;
  size_t start = 0;
  for (size_t p; (p = good.find('\n', start)) != std::string::npos; start = p + 1)
    lines.push_back(good.substr(start, p + 1 - start));
  for (size_t cut = 0; cut < lines.size(); ++cut) {
    std::string prefix, without;
    for (size_t i = 0; i < lines.size(); ++i) {
      if (i < cut) prefix += lines[i];
      if (i != cut) without += lines[i];
    }
    ParseResult a = parse(prefix), b = parse(without);
    EXPECT_TRUE(a.value || !a.errors.empty());
    EXPECT_TRUE(b.value || !b.errors.empty());
    for (const Error& e : b.errors) EXPECT_FALSE(e.message.empty());
  }
}

TEST(ParseCaseErrors, SingularInstanceTransform) {
  ParseResult r = parse(R"(rules: [R-INST-XFORM]
scene:
  blas:
    quad:
      - triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}
  instances:
    - {blas: quad, transform: {scale: [1, 0, 1]}}
rays:
  list: [{origin: [0, 0, 1], direction: [0, 0, -1]}]
)");
  expectError(r, 7, "scene.instances[0].transform", "not invertible");
}

}  // namespace
}  // namespace rayspec
