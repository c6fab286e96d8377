// The payload a trace starts with (`trace: {payload: ...}`): what the caller
// writes reaches the stages of that trace, and what they write comes back
// (R-PAYLOAD), in raygen and in a nested trace, in every tier.
#include "model_support.h"

namespace rayspec::model_test {
namespace {

// Ray 0 hits the triangle, ray 1 misses. Raygen traces twice: the second
// trace starts from the first one's result plus 5. Closest-hit adds 100 and
// traces again (nested, toward nothing) starting from its own payload times
// 2, and keeps the miss's answer (+1000) in value1.
const char* kStartPayload = R"(rules: [R-PAYLOAD]
scene:
  blas:
    tri:
      - triangles:
          vertices: [[-1, -1, 0], [2, -1, 0], [-1, 2, 0]]
  instances: [{blas: tri}]
rays:
  list:
    - {origin: [0, 0, 1], direction: [0, 0, -1]}
    - {origin: [50, 0, 1], direction: [0, 0, -1]}
pipeline:
  max_recursion: 2
  raygen:
    - trace: {payload: {value: 7, color: [1.0, 2.0, 3.0, 4.0]}}
    - record: {value: payload.value, color: payload.color}
    - trace: {payload: {value: {add: [payload.value, 5]}}}
    - record: {value2: payload.value, color2: payload.color}
  miss:
    - [payload: {value: {add: [payload.value, 1000]}}]
  hit_groups:
    - closest_hit:
        - payload: {value: {add: [payload.value, 100]}}
        - trace: {origin: [0.0, 0.0, 1.0], direction: [0.0, 0.0, 1.0],
                  payload: {value: {mul: [payload.value, 2]}}}
        - record: {value1: child.value}
outputs:
  per_ray: [value, value1, value2, color, color2]
)";

TEST(ModelPayload, ATraceStartsWithThePayloadItsStatementGives) {
  const Case c = parseInline(kStartPayload);
  for (ModelTier tier : kTiers) {
    const Results r = runTier(c, tier);
    SCOPED_TRACE(modelTierName(tier));
    // Hit: 7 + 100. The second trace starts at 112: 212.
    EXPECT_EQ(word(r, 0, "value"), 107u);
    EXPECT_EQ(word(r, 0, "value2"), 212u);
    // value1 as the second trace's closest-hit left it: its nested trace
    // starts at 2 x 212 and misses: 1424.
    EXPECT_EQ(word(r, 0, "value1"), 1424u);
    EXPECT_EQ(fword(r, 0, "color", 2), 3.0f) << "color comes back as it went in";
    EXPECT_EQ(fword(r, 0, "color2", 2), 0.0f) << "a field the trace does not give starts at 0";
    // Miss: 7 + 1000, then 1012 + 1000.
    EXPECT_EQ(word(r, 1, "value"), 1007u);
    EXPECT_EQ(word(r, 1, "value2"), 2012u);
  }
}

}  // namespace
}  // namespace rayspec::model_test
