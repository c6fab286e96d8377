// Static diagnosis of undefined behaviour in case files (R-UB where the values
// are constants) and the parser's messages: duplicate keys, rule labels,
// yaml-cpp exceptions, names that become file names.
#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "parse/parse_case.h"
#include "parse_support.h"
#include "suite_cases.h"

namespace rayspec {
namespace {

ParseResult parseDiagnostics(const std::string& text,
                             const std::vector<std::string>* catalog = nullptr) {
  return parseCaseText(text, "d.yaml", "family/d", catalog);
}

// The error at line:col whose field is `field` and whose message holds `text`.
const Error* errorAt(const ParseResult& r, int line, int column, const std::string& field,
                     const std::string& text) {
  for (const Error& e : r.errors)
    if (e.loc.line == line && (column == 0 || e.loc.column == column) && e.loc.field == field &&
        e.message.find(text) != std::string::npos)
      return &e;
  return nullptr;
}

#define EXPECT_ERROR_AT(r, line, column, field, text)                                              \
  EXPECT_TRUE(errorAt(r, line, column, field, text))                                               \
      << "expected " << line << ":" << column << ": " << field << ": ..." << text << "...; got:\n" \
      << allErrors(r)

// Two geometries under one instance; @HIT@ is the pipeline's hit groups and sbt.
const char* kTwoGeometries = R"(rules: [R-SBT-HIT]
scene:
  blas:
    pair:
      - triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}
      - triangles: {vertices: [[3, 0, 0], [4, 0, 0], [3, 1, 0]]}
  instances:
    - {blas: pair, mask: @MASK@}
rays:
  list:
    - {origin: [0, 0, 1], direction: [0, 0, -1]}
    - {origin: [0, 0, 1], direction: [0, 0, -1], sbt_offset: @OFFSET@}
pipeline:
  flags: @FLAGS@
  raygen:
    - trace: {}
  miss: [[]]
@HIT@
)";

std::string twoGeometries(const std::string& hit, const std::string& offset = "0",
                          const std::string& mask = "0xFF", const std::string& flags = "[]") {
  std::string s = kTwoGeometries;
  auto put = [&](const std::string& key, const std::string& value) {
    s.replace(s.find(key), key.size(), value);
  };
  put("@HIT@", hit);
  put("@OFFSET@", offset);
  put("@MASK@", mask);
  put("@FLAGS@", flags);
  return s;
}

TEST(CaseStaticUndefined, HitRecordBeyondTheHitRegionIsACaseError) {
  // Geometry 1 with stride 1 reads hit record 1; one hit group, no sbt block: one record.
  ParseResult r = parseDiagnostics(twoGeometries("  hit_groups: [{closest_hit: []}]"));
  EXPECT_ERROR_AT(r, 16, 7, "pipeline.raygen[0].trace", "hit record 1 is out of range");
  EXPECT_NE(allErrors(r).find("geometry 1"), std::string::npos);
  ASSERT_EQ(r.undefined.size(), 1u);
  EXPECT_EQ(r.undefined[0].reason, UndefinedReason::HitRecordOutOfRange);
  // A record per geometry (sbt block or a group each) is fine.
  EXPECT_TRUE(
      parseDiagnostics(twoGeometries("  hit_groups: [{closest_hit: []}]\n  sbt: {hit: [0, 0]}"))
          .value);
  EXPECT_TRUE(
      parseDiagnostics(twoGeometries("  hit_groups: [{closest_hit: []}, {closest_hit: []}]"))
          .value);
  // A launch ray's own sbt_offset (low 4 bits count) can reach beyond too; the message names the
  // ray.
  r = parseDiagnostics(twoGeometries("  hit_groups: [{}, {}]", "0x11"));
  EXPECT_ERROR_AT(r, 16, 7, "pipeline.raygen[0].trace", "hit record 2 is out of range");
  EXPECT_NE(allErrors(r).find("rays.list[1]"), std::string::npos) << allErrors(r);
  EXPECT_TRUE(parseDiagnostics(twoGeometries("  hit_groups: [{}, {}]", "0x10")).value)
      << "0x10 acts as 0 (R-SBT-HIT)";
  // Geometry nothing can reach: a masked-out instance, triangles skipped by the pipeline.
  EXPECT_TRUE(parseDiagnostics(twoGeometries("  hit_groups: [{}]", "0", "0")).value);
  EXPECT_TRUE(
      parseDiagnostics(twoGeometries("  hit_groups: [{}]", "0", "0xFF", "[skip_triangles]")).value);
}

TEST(CaseStaticUndefined, DynamicSbtValuesAreLeftToTheModel) {
  std::string text = twoGeometries("  hit_groups: [{}]");
  text.replace(text.find("trace: {}"), 9, "trace: {sbt_offset: launch_id_x, miss: launch_id_y}");
  const ParseResult r = parseDiagnostics(text);
  EXPECT_TRUE(r.value) << allErrors(r);
}

const char* kPrograms = R"(rules: [R-SBT-MISS, R-SBT-CALL]
rays:
  list: [{origin: [0, 0, 1], direction: [0, 0, -1]}]
pipeline:
  max_recursion: 2
  raygen:
    - trace: {miss: @MISS@}
    - call: {index: @CALL@}
  miss:
    - - trace: {origin: [0, 0, 0], direction: [0, 0, 1], tmin: @TMIN@, tmax: @TMAX@}
    - []
  callables:
    - [call_data: {value: 1}]
outputs:
  per_ray: [value]
)";

std::string programs(const std::string& miss, const std::string& call,
                     const std::string& tmin = "0.5", const std::string& tmax = "10") {
  std::string s = kPrograms;
  auto put = [&](const std::string& key, const std::string& value) {
    s.replace(s.find(key), key.size(), value);
  };
  put("@MISS@", miss);
  put("@CALL@", call);
  put("@TMIN@", tmin);
  put("@TMAX@", tmax);
  return s;
}

// A miss index beyond the miss region is undefined only for a ray that
// misses (R-SBT-MISS): the model judges it ray by ray (model_undefined_test).
TEST(CaseStaticUndefined, MissIndexBeyondTheMissRegionIsLeftToTheModel) {
  EXPECT_TRUE(parseDiagnostics(programs("1", "0")).value);
  ParseResult r = parseDiagnostics(programs("2", "0"));
  EXPECT_TRUE(r.value) << allErrors(r);
  r = parseDiagnostics(programs("{add: [1, 1]}", "0"));
  EXPECT_TRUE(r.value) << allErrors(r);
}

TEST(CaseStaticUndefined, CallableIndexBeyondTheCallableRegionIsACaseError) {
  ParseResult r = parseDiagnostics(programs("0", "1"));
  EXPECT_ERROR_AT(r, 8, 21, "pipeline.raygen[1].call.index", "callable index 1 is out of range");
  EXPECT_EQ(r.undefined.at(0).reason, UndefinedReason::CallableOutOfRange);
  r = parseDiagnostics(programs("0", "{mul: [3, 2]}"));
  EXPECT_ERROR_AT(r, 8, 21, "pipeline.raygen[1].call.index", "callable index 6");
  EXPECT_TRUE(parseDiagnostics(programs("0", "{sub: [launch_id_x, launch_id_x]}")).value)
      << "not a constant";
}

TEST(CaseStaticUndefined, NegativeOrNanTminAndTmaxBelowTminAreCaseErrors) {
  // In a trace.
  ParseResult r = parseDiagnostics(programs("0", "0", "-1"));
  EXPECT_ERROR_AT(r, 10, 64, "pipeline.miss[0][0].trace.tmin", "trace tmin is negative or NaN");
  r = parseDiagnostics(programs("0", "0", "2", "1"));
  EXPECT_ERROR_AT(r, 10, 73, "pipeline.miss[0][0].trace.tmax", "trace tmax is below tmin");
  // In rays: the defaults and a list entry.
  const std::string rays = R"(rules: [R-CAND-TRI-OPEN]
rays:
  list:
    - {origin: [0, 0, 1], direction: [0, 0, -1], tmax: 0.0001}
    - {origin: [0, 0, 1], direction: [0, 0, -1], tmin: .nan}
    - {origin: [0, .inf, 1], direction: [0, 0, -1]}
  tmin: 0.001
  tmax: -4
pipeline: {miss: [[]]}
)";
  r = parseDiagnostics(rays);
  EXPECT_ERROR_AT(r, 4, 56, "rays.list[0].tmax", "tmax 0.0001 is below tmin 0.001");
  EXPECT_ERROR_AT(r, 5, 56, "rays.list[1].tmin", "tmin is NaN");
  EXPECT_ERROR_AT(r, 6, 16, "rays.list[2].origin", "not finite");
  EXPECT_ERROR_AT(r, 8, 9, "rays.tmax", "tmax -4 is negative");
  for (const Error& e : r.errors)
    EXPECT_NE(e.message.find("R-UB"), std::string::npos) << e.format();
}

TEST(CaseStaticUndefined, UintDivisionOrModuloByAConstantZeroIsACaseError) {
  const std::string text = R"(rules: [R-BUILTIN]
rays:
  list: [{origin: [0, 0, 1], direction: [0, 0, -1]}]
pipeline:
  miss:
    - - record: {value: @EXPR@}
outputs:
  per_ray: [value]
)";
  auto with = [&](const std::string& e) {
    std::string s = text;
    s.replace(s.find("@EXPR@"), 6, e);
    return parseDiagnostics(s);
  };
  ParseResult r = with("{div: [launch_id_x, {sub: [2, 2]}]}");
  EXPECT_ERROR_AT(r, 6, 25, "pipeline.miss[0][0].record.value", "Uint division by a constant zero");
  r = with("{mod: [launch_id_x, {mul: [0, 5]}]}");
  EXPECT_ERROR_AT(r, 6, 25, "pipeline.miss[0][0].record.value", "Uint modulo by a constant zero");
  EXPECT_TRUE(with("{div: [7, launch_id_x]}").value) << "a dynamic divisor is the model's to judge";
  EXPECT_TRUE(with("{uint: {div: [1.0, 0.0]}}").value)
      << "Float division by zero is no undefined behaviour";
}

TEST(CaseStaticUndefined, ARobustnessProbeKeepsItsUndefinedBehaviour) {
  std::string text = programs("5", "0", "-1");
  text.replace(text.find("R-SBT-MISS"), 10, "R-UB");
  const ParseResult r = parseDiagnostics(text);
  ASSERT_TRUE(r.value) << allErrors(r);
  ASSERT_EQ(r.value->static_undefined.size(), 1u);
  EXPECT_EQ(r.value->static_undefined[0].reason, UndefinedReason::RayParameters);
  EXPECT_EQ(r.value->static_undefined[0].loc.field, "pipeline.miss[0][0].trace.tmin");
}

// C: no case of the suite reads outside its shader binding table where the
// values are constants (an R-UB probe neither: it would say so in its rules).
TEST(Suite, NoCaseReadsOutsideItsSbt) {
  namespace fs = std::filesystem;
  int count = 0;
  for (const CaseFile& f : suiteCases()) {
    ++count;
    const ParseResult r = loadSuiteCase(f);
    for (const StaticUndefined& u : r.undefined)
      EXPECT_TRUE(u.reason != UndefinedReason::HitRecordOutOfRange &&
                  u.reason != UndefinedReason::MissRecordOutOfRange &&
                  u.reason != UndefinedReason::CallableOutOfRange)
          << u.loc.file << ":" << u.loc.line << ":" << u.loc.column << ": " << u.loc.field << ": "
          << u.message;
  }
  EXPECT_GT(count, 0);
}

// The case that read outside its SBT: without its sbt block, geometry 1's hit
// record lies beyond the hit region, and the parser says so.
TEST(Suite, ClosestHitAndMissWithoutItsSbtBlockReadsOutside) {
  const std::string path =
      std::string(RAYSPEC_SOURCE_DIR) + "/cases/builtins/closest-hit-and-miss.yaml";
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  ASSERT_TRUE(parseCaseText(s, path, "builtins/closest-hit-and-miss").value);
  const size_t sbt = s.find("  sbt:\n");
  ASSERT_NE(sbt, std::string::npos);
  s.erase(sbt, s.find('\n', s.find("hit:", sbt)) + 1 - sbt);
  const ParseResult r = parseCaseText(s, path, "builtins/closest-hit-and-miss");
  EXPECT_FALSE(r.value);
  ASSERT_FALSE(r.undefined.empty());
  EXPECT_EQ(r.undefined[0].reason, UndefinedReason::HitRecordOutOfRange);
}

}  // namespace
}  // namespace rayspec
