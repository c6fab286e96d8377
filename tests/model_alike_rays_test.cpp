// Launch rays alike, traced once (model/alike_rays.h): the model's results
// with the memo are those of tracing every ray (ModelOptions::trace_each_ray),
// field for field, in every tier; where a stage reads the launch id the memo
// stays off, and each id keeps its own outcome.
#include <filesystem>

#include <nlohmann/json.hpp>

#include "base/whole_file.h"
#include "bundle/results_io.h"
#include "model/alike_rays.h"
#include "model/model_sbt.h"
#include "model_support.h"

namespace rayspec::model_test {
namespace {

// Rays in runs alike, as a grid with no step lays them: 0-2 and 9-10 the
// tie of boxes of cts-amber/basic2 (each ambiguous: the exact tier replays
// its answers), 3-4 a non-opaque triangle in an instance translated far
// (any-hit counts, so a floor; its object-space origin a bound), 5-6 tmax
// below tmin (undefined: each traced, its diagnosis names its index), 7-8 a
// sphere grazed (a t and a position bound);
// 9-10 the first ray again after others (traced again: only the last ray is
// kept).
const std::string kAlike = R"(rules: [R-TIE, R-UB, R-PREC]
scene:
  blas:
    boxes:
      - aabbs: [[-0.5, -0.75, -1, 0.5, 0.75, 1], [-0.33, -0.75, -1, 0.33, 0.75, 1]]
      - aabbs: [[-1.5, -1.75, -1, 1.5, 1.75, 1], [-2.33, -2.75, -2, 2.33, 2.75, 2]]
    tri:
      - triangles:
          vertices: [[0, -4, 0], [12, -4, 0], [0, 8, 0]]
    sphere: [{aabbs: [[-2, -2, -1, 2, 2, 1]], flags: [opaque]}]
  instances:
    - {blas: boxes, flags: [force_no_opaque]}
    - {blas: tri, sbt_offset: 1, transform: {translate: [1026, 0, 0]}}
    - {blas: sphere, sbt_offset: 2, transform: {translate: [-100, 0, 0]}}
rays:
  list:
    - {origin: [0.5, 0.5, 0], direction: [0, 0, -1]}
    - {origin: [0.5, 0.5, 0], direction: [0, 0, -1]}
    - {origin: [0.5, 0.5, 0], direction: [0, 0, -1]}
    - {origin: [1030.3, 0.2, 9], direction: [0, 0, -1], tmax: 20}
    - {origin: [1030.3, 0.2, 9], direction: [0, 0, -1], tmax: 20}
    - {origin: [0.5, 0.5, 0], direction: [0, 0, -1], tmin: 5, tmax: 1}
    - {origin: [0.5, 0.5, 0], direction: [0, 0, -1], tmin: 5, tmax: 1}
    - {origin: [-99.001, 0, 2], direction: [0, 0, -4], tmin: 0.001}
    - {origin: [-99.001, 0, 2], direction: [0, 0, -4], tmin: 0.001}
    - {origin: [0.5, 0.5, 0], direction: [0, 0, -1]}
    - {origin: [0.5, 0.5, 0], direction: [0, 0, -1]}
  tmin: 0
  tmax: 9
pipeline:
  raygen: [trace: {}]
  miss:
    - [count: miss, record: {hit: 0}]
  hit_groups:
    - intersection: [report: {t: 0.95, kind: 0x7E}]
      any_hit: [count: anyhit]
      closest_hit: [count: closesthit, record: [hit, hit_kind, hit_t, instance_id, geometry_index, primitive_id]]
    - any_hit: [count: anyhit]
      closest_hit: [count: closesthit, record: [hit, hit_t, instance_id, primitive_id, object_ray_origin]]
    - intersection:
        - if: sphere_hit
          then: [report: {t: sphere_near, kind: 1}]
      closest_hit: [count: closesthit, record: [hit, hit_t, hit_position]]
outputs:
  counters: [miss, closesthit, anyhit]
  per_ray: [hit, hit_kind, hit_t, instance_id, geometry_index, primitive_id, hit_position,
            object_ray_origin, value]
)";

// What the judge reads of `r`: results.json (its clock left out), and
// records.bin and replays.bin.
struct JudgedFiles {
  std::string json;
  std::string records, replays;
};
JudgedFiles judgedFiles(const Results& r, const std::string& name) {
  const std::string dir = ::testing::TempDir() + "alike-rays-" + name;
  std::filesystem::remove_all(dir);
  EXPECT_TRUE(writeResults(r, dir, {}, BundleFiles{false, false}).ok());
  auto read = [&](const char* file) {
    if (!std::filesystem::exists(dir + "/" + file)) return std::string();
    const Result<std::string> text = readWholeFile(dir + "/" + file, 1 << 24);
    EXPECT_TRUE(text.ok()) << file;
    return text.ok() ? *text : std::string();
  };
  nlohmann::json j = nlohmann::json::parse(read("results.json"));
  j.erase("seconds");
  j.erase("cost");
  return {j.dump(1), read("records.bin"), read("replays.bin")};
}

// Every field of the two runs the same (the records compared as bytes: a
// difference is not printed).
void expectSame(const Results& once, const Results& each) {
  const JudgedFiles a = judgedFiles(once, "once"), b = judgedFiles(each, "each");
  EXPECT_EQ(a.json, b.json);
  EXPECT_TRUE(a.records == b.records) << "records.bin differs";
  EXPECT_TRUE(a.replays == b.replays) << "replays.bin differs";
}

Results runAs(const Case& c, ModelTier tier, bool trace_each_ray, unsigned threads = 2) {
  ModelOptions o{tier, threads};
  o.trace_each_ray = trace_each_ray;
  return runOnModel(c, derivePlan(c), o);
}

TEST(ModelAlikeRays, RaysAlikeGiveWhatTracingEachGives) {
  const Case c = parseInline(kAlike);
  for (ModelTier tier : kTiers)
    for (unsigned threads : {1u, 2u}) {
      SCOPED_TRACE(std::string(modelTierName(tier)) + " threads " + std::to_string(threads));
      const Results each = runAs(c, tier, true, threads);
      const Results once = runAs(c, tier, false, threads);
      ASSERT_TRUE(each.ok()) << each.statusText();
      expectSame(once, each);
      if (tier != ModelTier::Exact) continue;
      // What the copies must carry is there: ambiguous rays with replays, a
      // t bound, undefined rays, floors.
      EXPECT_EQ(once.ambiguous.size(), 5u);
      ASSERT_NE(ambiguityOf(once, 10), nullptr);
      EXPECT_FALSE(ambiguityOf(once, 10)->replays.empty());
      EXPECT_EQ(once.undefined.size(), 2u);
      EXPECT_EQ(once.t_bounds.size(), 2u);
      EXPECT_EQ(once.position_bounds.size(), 2u);
      EXPECT_EQ(once.object_origin_bounds.size(), 2u);
      EXPECT_EQ(once.counter_floors.at("anyhit"), 2u);
    }
}

// The same rays, the hit group recording the launch id: the ids of one ray
// record apart, so the memo must not copy (model/uniform_launch.h launchIdRead).
TEST(ModelAlikeRays, AStageReadingTheLaunchIdIsTracedIdById) {
  std::string text = kAlike;
  const std::string from = "record: [hit, hit_t, instance_id, primitive_id, object_ray_origin]";
  ASSERT_NE(text.find(from), std::string::npos);
  text.replace(text.find(from), from.size(), "record: {hit: 1, value: launch_id_x}");
  const Case c = parseInline(text);
  for (ModelTier tier : kTiers) {
    SCOPED_TRACE(modelTierName(tier));
    const Results once = runAs(c, tier, false);
    ASSERT_TRUE(once.ok()) << once.statusText();
    EXPECT_EQ(word(once, 3, "value"), 3u);
    EXPECT_EQ(word(once, 4, "value"), 4u);
    expectSame(once, runAs(c, tier, true));
  }
}

// Read in any stage, not only where a record is written: the boxes' any-hit
// counts for launch id 1 alone, a ray alike 0 and 2.
TEST(ModelAlikeRays, ALaunchIdReadInAnAnyHitKeepsIdsApart) {
  std::string text = kAlike;
  const std::string from =
      "      any_hit: [count: anyhit]\n      closest_hit: [count: closesthit, record: [hit, "
      "hit_kind";
  ASSERT_NE(text.find(from), std::string::npos);
  text.replace(text.find(from), std::string("      any_hit: [count: anyhit]").size(),
               "      any_hit:\n"
               "        - if: {eq: [launch_id_x, 1]}\n"
               "          then: [count: anyhit]");
  const Case c = parseInline(text);
  for (ModelTier tier : kTiers) {
    SCOPED_TRACE(modelTierName(tier));
    const Results once = runAs(c, tier, false), each = runAs(c, tier, true);
    ASSERT_TRUE(once.ok()) << once.statusText();
    EXPECT_GT(each.counters.at("anyhit"), 2u);  // ray 1's, and rays 3-4's on the triangle
    EXPECT_EQ(once.counters, each.counters);
  }
}

// The memo's own bookkeeping on a LaunchState: what a traced ray left (its
// record, counter and floor moves, entries named by its index) is added
// again for a ray bit for bit the same, named by that ray; a ray differing
// in one bit (-0 against 0), a ray the next launch ray differs from, an
// undefined ray, or any ray with the memo off, is not.
TEST(ModelAlikeRays, ARepeatAddsWhatTheTracedRayLeft) {
  const Case c = parseInline(kAlike);
  const Plan plan = derivePlan(c);
  ModelShared shared;
  shared.c = &c;
  shared.plan = &plan;
  const ModelSbt sbt(c);
  std::vector<uint32_t> records(3 * recordWords(), 0);
  LaunchState st(shared, sbt, records.data());
  AlikeRays alike(true);
  const Ray ray = c.rays.rays[0];
  EXPECT_FALSE(alike.repeat(st, ray, 0));  // nothing traced yet
  st.counters[0] = 5;
  alike.starting(st, ray, &ray);
  st.startRay(0);
  st.counters[0] += 2;
  st.floors[1] += 3;
  st.rec[0] = 0xABCD;
  st.ambiguous.push_back(RayAmbiguity{});
  st.t_bounds.push_back({0, 0.5f});
  alike.traced(st, 0);
  EXPECT_TRUE(alike.repeat(st, ray, 2));
  EXPECT_EQ(st.counters[0], 9u);
  EXPECT_EQ(st.floors[1], 6u);
  EXPECT_EQ(records[2 * recordWords()], 0xABCDu);
  ASSERT_EQ(st.ambiguous.size(), 2u);
  EXPECT_EQ(st.ambiguous[1].ray, 2u);
  ASSERT_EQ(st.t_bounds.size(), 2u);
  EXPECT_EQ(st.t_bounds[1].ray, 2u);
  EXPECT_EQ(st.t_bounds[1].bound, 0.5f);
  Ray other = ray;
  other.origin[2] = -0.0f;
  EXPECT_FALSE(alike.repeat(st, other, 1));
  // Not kept where the launch ray after it differs; the one kept before stays.
  alike.starting(st, other, &ray);
  alike.traced(st, 1);
  EXPECT_FALSE(alike.repeat(st, other, 2));
  EXPECT_TRUE(alike.repeat(st, ray, 2));
  EXPECT_EQ(st.counters[0], 11u);
  // An undefined ray is not kept (its diagnosis names its index in text).
  alike.starting(st, other, &other);
  st.undefined.push_back({1, UndefinedReason::RayParameters, "rays: launch ray 1 tmax"});
  alike.traced(st, 1);
  EXPECT_FALSE(alike.repeat(st, other, 2));
  EXPECT_EQ(st.undefined.size(), 1u);
  AlikeRays off(false);
  off.starting(st, ray, &ray);
  off.traced(st, 0);
  EXPECT_FALSE(off.repeat(st, ray, 1));
  EXPECT_EQ(st.counters[0], 11u);
}

}  // namespace
}  // namespace rayspec::model_test
