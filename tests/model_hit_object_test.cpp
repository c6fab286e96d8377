// Hit objects in the model (GL_NV_shader_invocation_reorder, cases/README.md
// "Hit objects"): a trace into one runs no closest-hit or miss, its getters
// read the committed hit (or miss) and its SBT record, executing it runs
// what the trace would have run with that hit's built-ins, a miss recorded by
// hand runs its miss shader, and reorder changes nothing. The planted faults
// break each.
#include "model_support.h"

namespace rayspec::model_test {
namespace {

// Two quads, the second behind the first and translated, custom index 7 and
// SBT offset 1; ray 0 hits instance 0's triangle 1, ray 1 hits only instance
// 1 (its triangle 0), ray 2 misses.
std::string caseText(const std::string& raygen, const std::string& extra_outputs = "") {
  return "rules: [R-HIT-OBJECT]\n"
         "scene:\n"
         "  blas:\n"
         "    quad:\n"
         "      - triangles:\n"
         "          vertices: [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]]\n"
         "          indices: [0, 1, 2, 0, 2, 3]\n"
         "        flags: [opaque]\n"
         "  instances:\n"
         "    - {blas: quad}\n"
         "    - {blas: quad, transform: {translate: [3, 0, -2], scale: 2}, custom_index: 7, "
         "sbt_offset: 1}\n"
         "rays:\n"
         "  list:\n"
         "    - {origin: [-0.5, 0.25, 5], direction: [0, 0, -1]}\n"
         "    - {origin: [3.5, -0.5, 5], direction: [0, 0, -1]}\n"
         "    - {origin: [9, 9, 5], direction: [0, 0, -1], miss: 1}\n"
         "pipeline:\n"
         "  raygen:\n" +
         raygen +
         "  miss:\n"
         "    - [count: miss0]\n"
         "    - [count: miss1, payload: {value: 500}, record: {value3: {uint: ray_tmax}}]\n"
         "  hit_groups:\n"
         "    - closest_hit: [count: closesthit, payload: {value: {add: [payload.value, "
         "instance_custom_index]}}, record: {value3: primitive_id}]\n"
         "  sbt:\n"
         "    hit: [0, 0]\n"
         "outputs:\n"
         "  counters: [miss0, miss1, closesthit]\n"
         "  per_ray: [hit, value, value1, value2, value3, instance_id, instance_custom_index, "
         "primitive_id, hit_t" +
         extra_outputs + "]\n";
}

const std::string kGetters =
    "    - trace: {hit_object: true}\n"
    "    - record: {hit: hit_object.is_hit, value: hit_object.is_miss, value1: "
    "hit_object.sbt_record_index, hit_t: hit_object.t}\n"
    "    - if: {eq: [hit_object.is_hit, 1]}\n"
    "      then: [record: {instance_id: hit_object.instance_id, instance_custom_index: "
    "hit_object.instance_custom_index, primitive_id: hit_object.primitive_id}]\n";

TEST(HitObject, ATraceRunsNoClosestHitOrMissAndItsGettersReadTheCommittedHit) {
  const Results r = runTier(parseInline(caseText(kGetters)), ModelTier::Exact);
  EXPECT_EQ(r.counters.at("closesthit"), 0u);
  EXPECT_EQ(r.counters.at("miss0") + r.counters.at("miss1"), 0u);
  EXPECT_EQ(word(r, 0, "hit"), 1u);
  EXPECT_EQ(word(r, 0, "instance_id"), 0u);
  EXPECT_EQ(word(r, 0, "primitive_id"), 1u);  // (-0.5, 0.25) lies in triangle 0, 2, 3
  EXPECT_EQ(word(r, 0, "value1"), 0u);
  EXPECT_EQ(fword(r, 0, "hit_t"), 5.0f);
  EXPECT_EQ(word(r, 1, "instance_id"), 1u);
  EXPECT_EQ(word(r, 1, "instance_custom_index"), 7u);
  EXPECT_EQ(word(r, 1, "value1"), 1u);  // the instance's SBT offset 1
  EXPECT_EQ(fword(r, 1, "hit_t"), 7.0f);
  EXPECT_EQ(word(r, 2, "hit"), 0u);
  EXPECT_EQ(word(r, 2, "value"), 1u);   // a miss
  EXPECT_EQ(word(r, 2, "value1"), 1u);  // its miss index
  EXPECT_FALSE(written(r, 2, "instance_id"));
}

TEST(HitObject, ExecutingRunsWhatTheTraceWouldHaveRunWithItsPayload) {
  const std::string raygen =
      "    - trace: {hit_object: true}\n"
      "    - execute: {payload: {value: 40}}\n"
      "    - record: {value2: payload.value}\n";
  const Results r = runTier(parseInline(caseText(raygen)), ModelTier::Exact);
  EXPECT_EQ(r.counters.at("closesthit"), 2u);
  EXPECT_EQ(r.counters.at("miss1"), 1u);
  EXPECT_EQ(word(r, 0, "value2"), 40u);
  EXPECT_EQ(word(r, 0, "value3"), 1u);  // closest-hit reads its hit's primitive
  EXPECT_EQ(word(r, 1, "value2"), 47u);
  EXPECT_EQ(word(r, 2, "value2"), 500u);
}

TEST(HitObject, ARecordedMissRunsItsMissShaderWithItsRay) {
  const std::string raygen =
      "    - record_miss: {miss: 1, tmax: 12.5}\n"
      "    - record: {value: hit_object.is_miss, value1: hit_object.sbt_record_index, hit_t: "
      "hit_object.t}\n"
      "    - execute: {}\n"
      "    - record_empty\n"
      "    - record: {value2: hit_object.is_empty}\n";
  const Results r = runTier(parseInline(caseText(raygen)), ModelTier::Exact);
  EXPECT_EQ(r.counters.at("closesthit"), 0u);
  EXPECT_EQ(r.counters.at("miss1"), 3u);
  EXPECT_EQ(word(r, 0, "value"), 1u);
  EXPECT_EQ(word(r, 0, "value1"), 1u);
  EXPECT_EQ(fword(r, 0, "hit_t"), 12.5f);
  EXPECT_EQ(word(r, 0, "value3"), 12u);  // the miss shader's tmax, 12.5, truncated
  EXPECT_EQ(word(r, 0, "value2"), 1u);
}

TEST(HitObject, TheTraceShadesFaultRunsClosestHitAtTheTrace) {
  Case c = parseInline(caseText(kGetters));
  ModelOptions o{ModelTier::Exact, 2};
  o.faults.hit_object_trace_shades = true;
  const Results r = runOnModel(c, derivePlan(c), o);
  EXPECT_EQ(r.counters.at("closesthit"), 2u);
}

TEST(HitObject, EachGetterFaultMovesItsFamily) {
  Case c = parseInline(caseText(kGetters));
  ModelOptions o{ModelTier::Exact, 2};
  o.faults.hit_object_getter = HitObjectGetterFault::IdsSwapped;
  Results r = runOnModel(c, derivePlan(c), o);
  EXPECT_EQ(word(r, 1, "instance_id"), 7u);
  o.faults.hit_object_getter = HitObjectGetterFault::SbtIndexOfInstance;
  r = runOnModel(c, derivePlan(c), o);
  EXPECT_EQ(word(r, 2, "value1"), 0u);
  o.faults.hit_object_getter = HitObjectGetterFault::StateWrong;
  r = runOnModel(c, derivePlan(c), o);
  EXPECT_EQ(word(r, 2, "value"), 0u);
  o.faults.hit_object_getter = HitObjectGetterFault::TInitial;
  r = runOnModel(c, derivePlan(c), o);
  EXPECT_NE(fword(r, 0, "hit_t"), 5.0f);
}

TEST(HitObject, ReorderChangesNothing) {
  const std::string plain = kGetters + "    - execute: {}\n";
  const std::string reordered = kGetters +
                                "    - reorder: {hit_object: true}\n"
                                "    - reorder: {hint: launch_id_x, bits: 3}\n"
                                "    - reorder: {hit_object: true, hint: 5, bits: 32}\n"
                                "    - execute: {}\n";
  const Results a = runTier(parseInline(caseText(plain)), ModelTier::Exact);
  const Results b = runTier(parseInline(caseText(reordered)), ModelTier::Exact);
  EXPECT_EQ(a.counters, b.counters);
  for (uint32_t ray = 0; ray < 3; ++ray)
    for (const char* f : {"hit", "value", "value1", "value3", "primitive_id"})
      EXPECT_EQ(word(a, ray, f), word(b, ray, f)) << ray << " " << f;
}

TEST(HitObject, ReorderOutsideRaygenAndAHintWithoutBitsAreErrors) {
  const std::string text = caseText(kGetters);
  EXPECT_NE(firstErrorAfter(text, "[count: miss0]", "[reorder: {hint: 1, bits: 1}]")
                .find("not allowed in miss"),
            std::string::npos);
  EXPECT_NE(firstErrorAfter(text, "    - trace: {hit_object: true}\n", "    - reorder: {hint: 1}\n")
                .find("hint and bits"),
            std::string::npos);
}

}  // namespace
}  // namespace rayspec::model_test
