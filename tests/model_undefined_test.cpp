// Undefined behaviour (R-UB) in the model: each kind is diagnosed for exactly
// the rays that meet it (Results.undefined, the first reason, the case field
// named), never crashes or fails the run, in every tier, and leaves the other
// rays as they were. The cases are written inline as case files.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <string>

#include "model/model_scene.h"
#include "model_support.h"
#include "parse/parse_case.h"

namespace rayspec {
namespace {

using namespace model_test;

std::map<uint32_t, const UndefinedRay*> undefinedByRay(const Results& r) {
  std::map<uint32_t, const UndefinedRay*> m;
  for (const UndefinedRay& u : r.undefined) {
    EXPECT_EQ(m.count(u.ray), 0u) << "ray " << u.ray << " listed twice";
    m[u.ray] = &u;
  }
  return m;
}

struct Expected {
  UndefinedReason reason;
  std::string what;  // a part of the message: the case field and the numbers
};

// Exactly these rays are undefined, for these reasons, naming these fields.
void expectUndefined(const Results& r, const std::map<uint32_t, Expected>& expected,
                     const char* tier) {
  ASSERT_EQ(r.statusText(), "ok") << tier;
  const auto got = undefinedByRay(r);
  for (const auto& [ray, e] : expected) {
    ASSERT_EQ(got.count(ray), 1u) << tier << ": ray " << ray << " should be undefined";
    EXPECT_EQ(got.at(ray)->reason, e.reason)
        << tier << ": ray " << ray << " " << undefinedReasonName(got.at(ray)->reason) << ": "
        << got.at(ray)->what;
    EXPECT_NE(got.at(ray)->what.find(e.what), std::string::npos)
        << tier << ": ray " << ray << ": '" << got.at(ray)->what << "' lacks '" << e.what << "'";
  }
  for (const auto& [ray, u] : got)
    EXPECT_EQ(expected.count(ray), 1u) << tier << ": ray " << ray << " is defined, not " << u->what;
}

// ---- RecursionTooDeep ----------------------------------------------------

// Ray 0: raygen calls callable 0, which calls itself (unbounded on a device;
// the model's stack overflowed). Ray 1: closest-hit traces again at every
// depth, beyond max_recursion 2. Ray 2 does neither.
const char* kRecursion = R"(rules: [R-UB]
scene:
  blas:
    tri:
      - triangles:
          vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]
        flags: [opaque]
  instances:
    - {blas: tri}
rays:
  grid: {size: [3, 1], origin: [-0.5, 0, 1], du: [0.25, 0, 0], dv: [0, 0, 0], direction: [0, 0, -1]}
  tmin: 0.001
  tmax: 100
pipeline:
  max_recursion: 2
  raygen:
    - if: {eq: [launch_id_x, 0]}
      then: [call: {index: 0}]
    - trace: {}
  miss:
    - [count: miss]
  hit_groups:
    - closest_hit:
        - count: closesthit
        - if: {eq: [launch_id_x, 1]}
          then: [trace: {origin: [0.0, 0.0, 1.0], direction: [0.0, 0.0, -1.0]}]
        - record: {depth: depth}
  callables:
    - [count: calls, call: {index: 0}]
outputs:
  counters: [miss, closesthit, calls]
  per_ray: [depth]
)";

TEST(ModelUndefined, RecursionTooDeepIsDiagnosedNotACrash) {
  // In a child process: before the nesting limit the model's own stack overflowed.
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        const Case c = parseInline(kRecursion);
        const Results r = runTier(c, ModelTier::Exact, 1);
        std::exit(r.ok() && r.undefined.size() == 2 ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
  const Case c = parseInline(kRecursion);
  for (ModelTier tier : kTiers) {
    const Results r = runTier(c, tier);
    expectUndefined(r,
                    {{0,
                      {UndefinedReason::RecursionTooDeep,
                       "pipeline.callables[0][1].call: callables nested 3 deep"}},
                     {1,
                      {UndefinedReason::RecursionTooDeep,
                       "pipeline.hit_groups[0].closest_hit[1].then[0].trace: trace at depth 3 "
                       "exceeds pipeline.max_recursion 2"}}},
                    modelTierName(tier));
    // The documented way on: the nested call and trace are skipped.
    EXPECT_EQ(r.counters.at("calls"), 2u);       // ray 0: two levels ran, the third was skipped
    EXPECT_EQ(r.counters.at("closesthit"), 4u);  // rays 0 and 2 once, ray 1 at depths 1 and 2
    EXPECT_EQ(word(r, 1, "depth"), 1u);          // the outer closest-hit wrote last
    EXPECT_EQ(word(r, 2, "depth"), 1u);
  }
}

// ---- HitRecordOutOfRange, MissRecordOutOfRange, CallableOutOfRange -----

// One hit group, so one hit record. Instances: 0 in range; 1 record 1
// (opaque); 2 record 1, made non-opaque, behind the in-range opaque 3; 4
// record 1, opaque, behind the in-range opaque 5. Miss region [group 0,
// zero]; callable region [group 0, zero].
const char* kSbt = R"(rules: [R-UB]
scene:
  blas:
    tri:
      - triangles:
          vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]
        flags: [opaque]
  instances:
    - {blas: tri}
    - {blas: tri, transform: {translate: [10, 0, 0]}, sbt_offset: 1}
    - {blas: tri, transform: {translate: [20, 0, -1]}, sbt_offset: 1, flags: [force_no_opaque]}
    - {blas: tri, transform: {translate: [20, 0, 0]}}
    - {blas: tri, transform: {translate: [30, 0, -1]}, sbt_offset: 1}
    - {blas: tri, transform: {translate: [30, 0, 0]}}
rays:
  list:
    - {origin: [0, 0, 1], direction: [0, 0, -1]}
    - {origin: [10, 0, 1], direction: [0, 0, -1]}
    - {origin: [20, 0, 1], direction: [0, 0, -1]}
    - {origin: [30, 0, 1], direction: [0, 0, -1]}
    - {origin: [10, 0, 1], direction: [0, 0, -1], flags: [skip_closest_hit]}
    - {origin: [50, 0, 1], direction: [0, 0, -1], miss: 2}
    - {origin: [50, 0, 1], direction: [0, 0, -1], miss: 1}
    - {origin: [0, 0, 1], direction: [0, 0, -1]}
    - {origin: [0, 0, 1], direction: [0, 0, -1]}
    - {origin: [0, 0, 1], direction: [0, 0, -1], sbt_offset: 16}
  tmin: 0.001
  tmax: 100
pipeline:
  raygen:
    - trace: {}
    - if: {eq: [launch_id_x, 7]}
      then: [call: {index: 3}]
    - if: {eq: [launch_id_x, 8]}
      then: [call: {index: 1}]
  miss:
    - [count: miss, record: {hit: 0}]
  hit_groups:
    - closest_hit: [count: closesthit, record: [hit, instance_id]]
  callables:
    - [count: calls]
  sbt:
    miss: [0, zero]
    callable: [0, zero]
outputs:
  counters: [miss, closesthit, calls]
  per_ray: [hit, instance_id]
)";

TEST(ModelUndefined, ShaderBindingTableIndicesBeyondTheirRegion) {
  const Case c = parseInline(kSbt);
  for (ModelTier tier : kTiers) {
    const Results r = runTier(c, tier);
    expectUndefined(r,
                    {{1,
                      {UndefinedReason::HitRecordOutOfRange,
                       "pipeline.sbt.hit: record 1, the hit region has 1 (instance 1 sbt_offset 1 "
                       "+ geometry 0 x stride 1 + sbt_offset 0)"}},
                     // A device may meet the non-opaque triangle behind first and run its any-hit.
                     {2, {UndefinedReason::HitRecordOutOfRange, "(instance 2 sbt_offset 1"}},
                     {5,
                      {UndefinedReason::MissRecordOutOfRange,
                       "pipeline.sbt.miss: miss index 2, the miss region has 2"}},
                     {7,
                      {UndefinedReason::CallableOutOfRange,
                       "pipeline.raygen[1].then[0].call.index: callable 3, the SBT has 2"}}},
                    modelTierName(tier));
    // Defined: 3 (an opaque triangle behind is never looked up), 4
    // (SkipClosestHit reads no record), 6 and 8 (all-zero records, R-SBT-ZERO),
    // 9 (offset 16: only the low 4 bits count, R-SBT-HIT).
    EXPECT_EQ(word(r, 0, "instance_id"), 0u);
    EXPECT_EQ(word(r, 3, "instance_id"), 5u);
    EXPECT_EQ(word(r, 9, "hit"), 1u);
    EXPECT_EQ(word(r, 9, "instance_id"), 0u);
    EXPECT_EQ(word(r, 6, "miss_runs"), 0u);
    EXPECT_EQ(word(r, 8, "callable_runs"), 0u);
    // The documented way: no shader of a record beyond the region runs.
    EXPECT_EQ(word(r, 1, "closest_hit_runs"), 0u);
    EXPECT_EQ(word(r, 5, "miss_runs"), 0u);
    EXPECT_EQ(word(r, 7, "callable_runs"), 0u);
    EXPECT_EQ(r.counters.at("calls"), 0u);
  }
}

// The same without the calls and with every triangle opaque: raygen is
// `trace: {}` alone, so the fast and robust tiers take Embree's closest hit
// on the chunked direct path (model_fast_path.cpp); instance 2, opaque now,
// is never looked up behind instance 3.
TEST(ModelUndefined, ShaderBindingTableRangesOnTheDirectPath) {
  std::string text = kSbt;
  const size_t from = text.find("  raygen:\n"), to = text.find("  miss:\n");
  text.replace(from, to - from, "  raygen: [trace: {}]\n");
  text.replace(text.find(", flags: [force_no_opaque]"),
               std::string(", flags: [force_no_opaque]").size(), "");
  const Case c = parseInline(text);
  for (ModelTier tier : kTiers) {
    const Results r = runTier(c, tier);
    expectUndefined(r,
                    {{1, {UndefinedReason::HitRecordOutOfRange, "(instance 1 sbt_offset 1"}},
                     {5, {UndefinedReason::MissRecordOutOfRange, "miss index 2"}}},
                    modelTierName(tier));
    EXPECT_EQ(word(r, 2, "instance_id"), 3u);
  }
}

// A pipeline without a miss shader (no miss region at all) is legal while
// no ray misses: the miss record is looked up only by a miss (R-SBT-MISS).
TEST(ModelUndefined, NoMissShaderIsUndefinedOnlyForARayThatMisses) {
  const std::string text = std::string("rules: [R-UB]\n") + kTriangleHitAndMiss + R"(pipeline:
  raygen: [trace: {}, trace: {origin: [0.5, 0, 1]}]
  hit_groups:
    - closest_hit: [record: [hit]]
outputs:
  per_ray: [hit]
)";
  const Case c = parseInline(text);
  for (ModelTier tier : kTiers) {
    const Results r = runTier(c, tier);
    expectUndefined(r,
                    {{1,
                      {UndefinedReason::MissRecordOutOfRange,
                       "pipeline.sbt.miss: miss index 0, the miss region has 0"}}},
                    modelTierName(tier));
    EXPECT_EQ(word(r, 0, "hit"), 1u);
  }
}

// ---- NullShader (R-NULL-SHADERS) -------------------------------------------

// Ray 0 hits through record 0; ray 1 hits the triangle of the all-zero hit
// record 1; ray 2 misses through the all-zero miss record 1; ray 3 misses
// through miss record 0. FLAGS and OPACITY are filled in by each test.
const char* kNullShader = R"(rules: [R-UB]
scene:
  blas:
    tri:
      - triangles:
          vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]
        flags: OPACITY
  instances:
    - {blas: tri}
    - {blas: tri, sbt_offset: 1, transform: {translate: [10, 0, 0]}}
rays:
  list:
    - {origin: [0, 0, 1], direction: [0, 0, -1]}
    - {origin: [10, 0, 1], direction: [0, 0, -1]}
    - {origin: [50, 0, 1], direction: [0, 0, -1], miss: 1}
    - {origin: [50, 0, 1], direction: [0, 0, -1]}
pipeline:
  flags: FLAGS
  miss:
    - [record: {hit: 0}]
  hit_groups:
    - any_hit: [record: {value1: 5}]
      closest_hit: [record: {hit: 1}]
  sbt:
    miss: [0, zero]
    hit: [0, zero]
outputs:
  per_ray: [hit, value1]
)";

Case nullShaderCase(const std::string& flags, const std::string& opacity) {
  std::string text = kNullShader;
  text.replace(text.find("FLAGS"), 5, flags);
  text.replace(text.find("OPACITY"), 7, opacity);
  return parseInline(text);
}

TEST(ModelUndefined, AZeroRecordWhereANoNullFlagPromisesAShader) {
  const std::string any_hit = "pipeline.sbt.hit: record 1 is all zero where an any-hit would run";
  const std::string closest =
      "pipeline.sbt.hit: record 1 is all zero where a closest-hit would run";
  const std::string miss = "pipeline.sbt.miss: record 1 is all zero where a miss shader would run";
  struct Variant {
    const char* flags;
    const char* opacity;
    std::map<uint32_t, Expected> undefined;
  };
  const Variant variants[] = {
      {"[]", "[]", {}},  // without a flag a zero record runs nothing: defined
      {"[no_null_any_hit]", "[]", {{1, {UndefinedReason::NullShader, any_hit}}}},
      // An opaque triangle runs no any-hit: the promise is not tested.
      {"[no_null_any_hit]", "[opaque]", {}},
      {"[no_null_closest_hit]", "[opaque]", {{1, {UndefinedReason::NullShader, closest}}}},
      {"[no_null_miss]", "[]", {{2, {UndefinedReason::NullShader, miss}}}},
      {"[no_null_any_hit, no_null_miss]",
       "[]",
       {{1, {UndefinedReason::NullShader, "no_null_any_hit"}},
        {2, {UndefinedReason::NullShader, "no_null_miss"}}}},
  };
  for (const Variant& v : variants) {
    SCOPED_TRACE(std::string(v.flags) + " " + v.opacity);
    const Case c = nullShaderCase(v.flags, v.opacity);
    for (ModelTier tier : kTiers) {
      const Results r = runTier(c, tier);
      expectUndefined(r, v.undefined, modelTierName(tier));
      EXPECT_EQ(word(r, 0, "hit"), 1u);
    }
  }
}

TEST(ModelUndefined, NoNullFlagsNeedTheShaderInEveryHitGroup) {
  std::string text = kNullShader;
  text.replace(text.find("FLAGS"), 5, "[no_null_any_hit, no_null_closest_hit]");
  text.replace(text.find("OPACITY"), 7, "[]");
  text.replace(text.find("    - any_hit: [record: {value1: 5}]\n"), 37, "    - ");
  const ParseResult p = parseCaseText(text, "model/inline.yaml", "model/inline");
  ASSERT_EQ(p.errors.size(), 1u);
  EXPECT_EQ(p.errors[0].loc.field, "pipeline.hit_groups[0]");
  EXPECT_NE(p.errors[0].message.find("no_null_any_hit, so every hit group needs an any_hit"),
            std::string::npos)
      << p.errors[0].message;
}

// ---- DivisionByZero -------------------------------------------------------

const char* kDivision = R"(rules: [R-UB]
scene:
  blas:
    tri:
      - triangles:
          vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]
        flags: [opaque]
  instances:
    - {blas: tri}
rays:
  grid: {size: [3, 1], origin: [-0.5, 0, 1], du: [0.25, 0, 0], dv: [0, 0, 0], direction: [0, 0, -1]}
  tmin: 0.001
  tmax: 100
pipeline:
  raygen:
    - trace: {}
    - record: {value: {div: [100, launch_id_x]}}
  miss:
    - [record: {hit: 0}]
  hit_groups:
    - closest_hit: [record: {hit: 1, value1: {mod: [7, {sub: [launch_id_x, 1]}]}}]
outputs:
  counters: []
  per_ray: [hit, value1, value]
)";

TEST(ModelUndefined, UintDivisionAndModuloByZero) {
  const Case c = parseInline(kDivision);
  for (ModelTier tier : kTiers) {
    const Results r = runTier(c, tier);
    // Ray 1's modulo runs in closest-hit, before raygen's division by 1.
    expectUndefined(
        r,
        {{0,
          {UndefinedReason::DivisionByZero,
           "pipeline.raygen[1].record.value: uint division by zero"}},
         {1,
          {UndefinedReason::DivisionByZero,
           "pipeline.hit_groups[0].closest_hit[0].record.value1: uint modulo by zero"}}},
        modelTierName(tier));
    EXPECT_EQ(word(r, 2, "value"), 50u);
    EXPECT_EQ(word(r, 2, "value1"), 0u);          // 7 mod 1
    EXPECT_EQ(word(r, 0, "value"), 0xFFFFFFFFu);  // the documented value
  }
}

// ---- RayParameters ---------------------------------------------------------

const char* kRays = R"(rules: [R-UB]
scene:
  blas:
    tri:
      - triangles:
          vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]
        flags: [opaque]
  instances:
    - {blas: tri}
rays:
  list:
    - {origin: [0, 0, 1], direction: [0, 0, -1]}
    - {origin: [.nan, 0, 1], direction: [0, 0, -1]}
    - {origin: [0, 0, 1], direction: [0, .inf, -1]}
    - {origin: [0, 0, 1], direction: [0, 0, -1], tmin: .nan}
    - {origin: [0, 0, 1], direction: [0, 0, -1], tmin: -1}
    - {origin: [0, 0, 1], direction: [0, 0, -1], tmin: 5, tmax: 1}
    - {origin: [0, 0, 1], direction: [0, 0, -1], tmax: .nan}
    - {origin: [0, 0, 1], direction: [0, 0, -1], flags: [opaque, no_opaque]}
    - {origin: [0, 0, 1], direction: [0, 0, 0]}
    - {origin: [0, 0, 1], direction: [0, 0, -1], cull_mask: 0}
    - {origin: [0, 0, 1], direction: [0, 0, -1], flags: [cull_back_facing, cull_front_facing]}
    - {origin: [0, 0, 1], direction: [0, 0, -1], tmin: -0.0}
  tmin: 0.001
  tmax: 100
pipeline:
  max_recursion: 2
  raygen: [trace: {}]
  miss:
    - [count: miss, record: {hit: 0}]
  hit_groups:
    - closest_hit:
        - count: closesthit
        - record: [hit]
        - if: {eq: [launch_id_x, 0]}
          then: [trace: {origin: [0.0, 0.0, 1.0], direction: [0.0, 0.0, -1.0], tmin: -1.0}]
outputs:
  counters: [miss, closesthit]
  per_ray: [hit]
)";

TEST(ModelUndefined, RayParameters) {
  const Case c = parseInline(kRays);
  for (ModelTier tier : kTiers) {
    const Results r = runTier(c, tier);
    expectUndefined(
        r,
        {{0,
          {UndefinedReason::RayParameters,
           "pipeline.hit_groups[0].closest_hit[2].then[0].trace.tmin: -1 < 0"}},
         {1,
          {UndefinedReason::RayParameters, "rays: launch ray 1 origin: (nan, 0, 1) is not finite"}},
         {2,
          {UndefinedReason::RayParameters,
           "rays: launch ray 2 direction: (0, inf, -1) is not finite"}},
         {3, {UndefinedReason::RayParameters, "launch ray 3 tmin: NaN"}},
         {4, {UndefinedReason::RayParameters, "launch ray 4 tmin: -1 < 0"}},
         {5, {UndefinedReason::RayParameters, "launch ray 5 tmax: 1 < tmin 5"}},
         {6, {UndefinedReason::RayParameters, "launch ray 6 tmax: NaN"}},
         {7, {UndefinedReason::RayParameters, "launch ray 7 flags: opaque and no_opaque together"}},
         {10,
          {UndefinedReason::RayParameters,
           "flags: cull_back_facing and cull_front_facing together"}}},
        modelTierName(tier));
    // Defined: a zero direction and a zero cull mask find nothing; -0 is not below 0.
    EXPECT_EQ(word(r, 8, "hit"), 0u);
    EXPECT_EQ(word(r, 9, "hit"), 0u);
    EXPECT_EQ(word(r, 11, "hit"), 1u);
    // The documented way: an undefined ray finds nothing and misses.
    EXPECT_EQ(word(r, 1, "miss_runs"), 1u);
    // Ray 0's launch trace is fine: its closest-hit ran, then the nested trace missed.
    EXPECT_EQ(word(r, 0, "closest_hit_runs"), 1u);
    EXPECT_EQ(word(r, 0, "miss_runs"), 1u);
  }
}

// ---- NanTriangle -----------------------------------------------------------

// Primitive 0 has NaN in Y (x in [0, 1], z = 0, any y), primitive 1 NaN in Z
// (x in [5, 6], y in [0, 1], any z). Instance 2 repeats them at x + 20 with
// mask 0x02. An opaque floor (instance 1) lies below everything.
const char* kNanTriangles = R"(rules: [R-UB]
scene:
  blas:
    tris:
      - triangles:
          vertices: [[0, .nan, 0], [1, 0, 0], [0, 1, 0], [5, 0, 0], [6, 0, 0], [5, 1, .nan]]
        flags: [opaque]
    floor:
      - triangles:
          vertices: [[-100, -200, -1], [300, -200, -1], [-100, 200, -1]]
        flags: [opaque]
  instances:
    - {blas: tris}
    - {blas: floor}
    - {blas: tris, transform: {translate: [20, 0, 0]}, mask: 0x02}
rays:
  list:
    - {origin: [0.5, 50, 1], direction: [0, 0, -1]}
    - {origin: [2, 0.5, 1], direction: [0, 0, -1]}
    - {origin: [5.5, 0.5, 1], direction: [0, 0, -1]}
    - {origin: [5.5, 3, 1], direction: [0, 0, -1]}
    - {origin: [20.5, 50, 1], direction: [0, 0, -1], cull_mask: 0x01}
    - {origin: [20.5, 50, 1], direction: [0, 0, -1]}
    - {origin: [0.5, 50, 1], direction: [0, 0, -1], flags: [cull_opaque]}
    - {origin: [0.5, 50, 1], direction: [0, 0, -1], flags: [skip_triangles]}
    - {origin: [0.5, 50, 1], direction: [0, 0, 1]}
    - {origin: [-3, 50, 0], direction: [1, 0, 0]}
  tmin: 0.001
  tmax: 100
pipeline:
  miss:
    - [count: miss, record: {hit: 0}]
  hit_groups:
    - closest_hit: [count: closesthit, record: [hit, instance_id, primitive_id]]
outputs:
  counters: [miss, closesthit]
  per_ray: [hit, instance_id, primitive_id]
)";

TEST(ModelUndefined, TrianglesWithNanInYOrZ) {
  const Case c = parseInline(kNanTriangles);
  for (ModelTier tier : kTiers) {
    const Results r = runTier(c, tier);
    expectUndefined(
        r,
        {{0,
          {UndefinedReason::NanTriangle,
           "scene.blas.tris[0]: triangle 0 has NaN in Y or Z (instance 0)"}},
         {2, {UndefinedReason::NanTriangle, "triangle 1 has NaN in Y or Z (instance 0)"}},
         {5, {UndefinedReason::NanTriangle, "triangle 0 has NaN in Y or Z (instance 2)"}},
         {9, {UndefinedReason::NanTriangle, "triangle 0 has NaN in Y or Z (instance 0)"}}},
        modelTierName(tier));
    // Defined: beside the regions (1, 3), masked out (4), culled as opaque
    // (6), skipped triangles (7), pointing away (8). Rays 1, 3 and 4 reach
    // the floor: a triangle of the model's own test in one BLAS must not hide
    // Embree's triangles of another (fast and robust tiers).
    for (uint32_t ray : {1u, 3u, 4u}) {
      EXPECT_EQ(word(r, ray, "hit"), 1u) << modelTierName(tier) << " ray " << ray;
      EXPECT_EQ(word(r, ray, "instance_id"), 1u) << modelTierName(tier) << " ray " << ray;
    }
    for (uint32_t ray : {6u, 7u, 8u})
      EXPECT_EQ(word(r, ray, "hit"), 0u) << modelTierName(tier) << " ray " << ray;
    // The documented way: such a triangle is never a hit.
    EXPECT_EQ(word(r, 0, "instance_id"), 1u);
  }
}

// The region of a NaN triangle through a geometry transform: a rotation
// about z turns the unbounded Y into unbounded X and Y; Z stays bounded.
TEST(ModelUndefined, NanTriangleRegionThroughATransform) {
  const std::array<Vec3, 3> tri = {Vec3{0, NAN, 2}, Vec3{1, 0, 2}, Vec3{0, 1, 3}};
  EXPECT_TRUE(triangleNanYZ(tri));
  EXPECT_FALSE(triangleInactive(tri));
  const auto plain = nanTriangleRegion(tri, std::nullopt);
  EXPECT_EQ(plain, (std::array<double, 6>{0, -INFINITY, 2, 1, INFINITY, 3}));
  const Transform rotate = {0, -1, 0, 10, 1, 0, 0, 0, 0, 0, 1, 0};  // (x, y) -> (10 - y, x)
  const auto turned = nanTriangleRegion(tri, rotate);
  EXPECT_EQ(turned, (std::array<double, 6>{-INFINITY, 0, 2, INFINITY, 1, 3}));
  const std::array<Vec3, 3> inactive = {Vec3{NAN, NAN, 0}, Vec3{1, 0, 0}, Vec3{0, 1, 0}};
  EXPECT_FALSE(triangleNanYZ(inactive));
}

// A triangle with NaN in Y under a geometry transform stays a NaN triangle:
// the transform spreads the NaN to X, but activity is decided on the
// vertices as given (R-INACTIVE), so the rays crossing it are undefined.
TEST(ModelUndefined, NanTriangleUnderAGeometryTransformIsNotInactive) {
  Geometry g = quad(0);
  g.vertices[2][1] = NAN;  // triangles 0 and 1 share vertex 2
  g.transform = Transform{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
  Case c = baseCase({g}, {downRay(0.5f, -0.5f), downRay(5, 5)});
  for (ModelTier tier : kTiers) {
    const Results r = run(c, tier);
    ASSERT_EQ(r.statusText(), "ok");
    ASSERT_EQ(r.undefined.size(), 1u) << modelTierName(tier);
    EXPECT_EQ(r.undefined[0].ray, 0u);
    EXPECT_EQ(r.undefined[0].reason, UndefinedReason::NanTriangle);
  }
}

}  // namespace
}  // namespace rayspec
