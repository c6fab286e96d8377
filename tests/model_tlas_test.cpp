// Several top levels (scene.instances[].tlas, trace: {tlas: k}): a trace
// finds only the instances of the level it names, and gl_InstanceID is the
// instance's position in the scene's list whichever level holds it.
#include "model_support.h"

namespace rayspec::model_test {
namespace {

// Three instances of one triangle at z = 0, x = 0, 10, 20: instance 0 and 2
// on level 0, instance 1 on level 2 (level 1 is empty). Each ray traces
// toward all three levels in turn, recording the instance it hits on each
// (value, value1, value2; 99 for a miss).
const char* kLevels = R"(rules: [R-INACTIVE]
scene:
  blas:
    tri:
      - triangles:
          vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]
  instances:
    - {blas: tri}
    - {blas: tri, tlas: 2, transform: {translate: [10, 0, 0]}}
    - {blas: tri, transform: {translate: [20, 0, 0]}}
rays:
  list:
    - {origin: [0, 0, 1], direction: [0, 0, -1]}
    - {origin: [10, 0, 1], direction: [0, 0, -1]}
    - {origin: [20, 0, 1], direction: [0, 0, -1]}
pipeline:
  raygen:
    - trace: {}
    - record: {value: payload.value}
    - trace: {tlas: 1}
    - record: {value1: payload.value}
    - trace: {tlas: 2}
    - record: {value2: payload.value}
  miss:
    - [payload: {value: 99}]
  hit_groups:
    - closest_hit: [payload: {value: instance_id}]
outputs:
  per_ray: [value, value1, value2]
)";

TEST(ModelTlas, ATraceFindsOnlyTheInstancesOfItsLevel) {
  const Case c = parseInline(kLevels);
  EXPECT_EQ(c.scene.tlasCount(), 3u);
  for (ModelTier tier : kTiers) {
    const Results r = runTier(c, tier);
    SCOPED_TRACE(modelTierName(tier));
    EXPECT_EQ(word(r, 0, "value"), 0u);
    EXPECT_EQ(word(r, 1, "value"), 99u) << "instance 1 is on level 2";
    EXPECT_EQ(word(r, 2, "value"), 2u) << "gl_InstanceID counts every level's instances";
    for (uint32_t ray = 0; ray < 3; ++ray)
      EXPECT_EQ(word(r, ray, "value1"), 99u) << "level 1 is empty";
    EXPECT_EQ(word(r, 0, "value2"), 99u);
    EXPECT_EQ(word(r, 1, "value2"), 1u);
    EXPECT_EQ(word(r, 2, "value2"), 99u);
  }
}

TEST(ModelTlas, ATraceOfALevelTheSceneLacksIsAnError) {
  std::string text = kLevels;
  text.replace(text.find("tlas: 2}\n    - record: {value2"), 7, "tlas: 3");
  const ParseResult p = parseCaseText(text, "model/inline.yaml", "model/inline");
  ASSERT_FALSE(p.value.has_value());
  ASSERT_FALSE(p.errors.empty());
  EXPECT_NE(p.errors[0].format().find("top level 3, but the scene has 3"), std::string::npos)
      << p.errors[0].format();
  EXPECT_EQ(p.errors[0].loc.field, "pipeline.raygen[4].trace.tlas");
}

}  // namespace
}  // namespace rayspec::model_test
