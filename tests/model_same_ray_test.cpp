// rays.same on the model: every launch id traces the one ray, its launch id
// its own, in every tier; with no per-ray outputs the model keeps no records,
// only counters.
#include "model_support.h"

namespace rayspec::model_test {
namespace {

// Odd ids trace with cull mask 1 and hit the triangle, even ids miss it.
const std::string kSameRay = R"(rules: [R-LAUNCH-3D]
scene:
  blas:
    tri:
      - triangles:
          vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]
  instances: [{blas: tri, mask: 1}]
rays:
  same: {origin: [0, 0, 1], direction: [0, 0, -1]}
  launch: [5, 2, 1]
pipeline:
  raygen:
    - count: raygen
    - trace: {cull_mask: {mod: [launch_id_x, 2]}}
    - record: {value: {add: [launch_id_x, {mul: [launch_id_y, 100]}]}}
  miss:
    - [count: miss]
  hit_groups:
    - closest_hit: [count: closesthit, record: [hit]]
outputs:
  counters: [raygen, miss, closesthit]
  per_ray: [hit, value]
)";

TEST(ModelSameRay, EveryLaunchIdTracesTheOneRay) {
  const Case c = parseInline(kSameRay);
  ASSERT_TRUE(c.rays.same);
  for (ModelTier tier : kTiers) {
    SCOPED_TRACE(modelTierName(tier));
    const Results r = runTier(c, tier);
    ASSERT_TRUE(r.ok()) << r.statusText();
    EXPECT_EQ(r.counters.at("raygen"), 10u);
    EXPECT_EQ(r.counters.at("closesthit"), 4u);  // x = 1, 3 in both rows
    EXPECT_EQ(r.counters.at("miss"), 6u);
    for (uint32_t id = 0; id < 10; ++id) {
      const uint32_t x = id % 5, y = id / 5;
      EXPECT_EQ(word(r, id, "value"), x + 100 * y) << id;
      EXPECT_EQ(word(r, id, "hit"), x % 2) << id;
    }
  }
}

TEST(ModelSameRay, CountersAloneKeepNoRecords) {
  std::string text = kSameRay;
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"  per_ray: [hit, value]\n", ""},
           {"    - record: {value: {add: [launch_id_x, {mul: [launch_id_y, 100]}]}}\n", ""},
           {", record: [hit]", ""},
           {"launch: [5, 2, 1]", "launch: [70001, 1, 1]"}}) {
    ASSERT_NE(text.find(from), std::string::npos) << from;
    text.replace(text.find(from), from.size(), to);
  }
  const Case c = parseInline(text);
  const Results r = runTier(c, ModelTier::Fast);
  ASSERT_TRUE(r.ok()) << r.statusText();
  EXPECT_TRUE(r.records.empty());
  EXPECT_EQ(r.counters.at("raygen"), 70001u);
  EXPECT_EQ(r.counters.at("closesthit"), 35000u);
  EXPECT_EQ(r.counters.at("miss"), 35001u);
}

// Every id alike (no program reads the launch id, no records): the model
// traces one id and multiplies its counts (model/uniform_launch.h). The
// same case with a read of the id that changes nothing is traced id by id,
// and counts the same; 2^30 ids take no longer than one.
const std::string kUniform = R"(rules: [R-LAUNCH-3D]
scene:
  blas:
    tri:
      - triangles:
          vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]
  instances: [{blas: tri}]
rays:
  same: {origin: [0, 0, 1], direction: [0, 0, -1]}
  launch: [@SIZE@]
pipeline:
  raygen:
    - if: "@IF@"
      then: [count: raygen]
    - trace: {}
    - trace: {cull_mask: 0}
  miss:
    - [count: miss]
  hit_groups:
    - closest_hit: [count: closesthit]
      any_hit: [count: anyhit]
outputs:
  counters: [raygen, miss, closesthit, anyhit]
)";

Case uniformCase(const std::string& launch, const std::string& condition) {
  std::string text = kUniform;
  text.replace(text.find("@SIZE@"), 6, launch);
  text.replace(text.find("\"@IF@\""), 6, condition);
  return parseInline(text);
}

TEST(ModelSameRay, AUniformLaunchCountsAsIdById) {
  const Results one =
      runTier(uniformCase("300, 7, 2", "{eq: [launch_size_z, 2]}"), ModelTier::Fast);
  const Results each = runTier(uniformCase("300, 7, 2", "{ge: [launch_id_x, 0]}"), ModelTier::Fast);
  ASSERT_TRUE(one.ok()) << one.statusText();
  ASSERT_TRUE(each.ok()) << each.statusText();
  EXPECT_EQ(one.counters.at("raygen"), 4200u);
  EXPECT_EQ(one.counters.at("closesthit"), 4200u);
  EXPECT_EQ(one.counters.at("miss"), 4200u);
  EXPECT_EQ(one.counters, each.counters);
  EXPECT_EQ(one.counter_floors, each.counter_floors);
}

TEST(ModelSameRay, TheLargestLaunchIsOneIdMultiplied) {
  const Case c = uniformCase("131072, 8192, 1", "{eq: [launch_size_y, 8192]}");
  const Results r = runTier(c, ModelTier::Exact);
  ASSERT_TRUE(r.ok()) << r.statusText();
  EXPECT_EQ(r.counters.at("raygen"), uint64_t{1} << 30);
  EXPECT_EQ(r.counters.at("miss"), uint64_t{1} << 30);
  EXPECT_EQ(r.counters.at("closesthit"), uint64_t{1} << 30);
  EXPECT_LT(r.seconds, 5.0);
}

}  // namespace
}  // namespace rayspec::model_test
