// Callable data types by location (pipeline.callable_data): their words
// travel from a call to the callable and back in every tier, a location or
// word outside the declared types is an error at the case line, a callable of
// another type than the call's makes that ray undefined (R-UB).
#include "model_support.h"

namespace rayspec::model_test {
namespace {

// Raygen calls callable 0 (location 1, six words) with words 0 and 5;
// callable 0 calls callable 1 (location 2, two words) and keeps its answer;
// the closest-hit calls callable 1 itself.
const std::string kCallDataTypes = std::string("rules: [R-CALLABLE]\n") + kTriangleHitAndMiss +
                                   R"(pipeline:
  callable_data: [{}, {words: 6}, {words: 2}]
  raygen:
    - call: {index: 0, location: 1, word0: {add: [launch_id_x, 10]}, word5: 50, value: 1}
    - record: {value: callee.word0, value1: callee.word5, value2: callee.value}
    - trace: {}
    - record: {value3: payload.value}
  miss:
    - [payload: {value: 9}]
  hit_groups:
    - closest_hit:
        - call: {index: 1, location: 2, word1: 8}
        - payload: {value: {add: [callee.word1, callee.value]}}
  callables:
    - call_data: 1
      program:
        - call: {index: 1, location: 2, word1: call.word5}
        - call_data: {word5: {add: [call.word0, callee.word1]}, word0: callee.value}
    - {call_data: 2, program: [call_data: {word1: {mul: [call.word1, 3]}, value: 4}]}
outputs:
  per_ray: [value, value1, value2, value3]
)";

TEST(ModelCallData, CallDataWordsTravelWithTheTypeOfTheirLocation) {
  const Case c = parseInline(kCallDataTypes);
  ASSERT_EQ(c.pipeline.call_data_words, (std::vector<uint32_t>{0, 6, 2}));
  ASSERT_EQ(c.pipeline.callable_data, (std::vector<uint32_t>{1, 2}));
  for (ModelTier tier : kTiers) {
    const Results r = runTier(c, tier);
    SCOPED_TRACE(modelTierName(tier));
    ASSERT_TRUE(r.undefined.empty()) << r.undefined[0].what;
    for (uint32_t ray : {0u, 1u}) {
      // Callable 1 returns word 1 = 3 x 50 and value 4: callable 0 keeps 4
      // in word 0 and (ray + 10) + 150 in word 5; value stays 1.
      EXPECT_EQ(word(r, ray, "value"), 4u);
      EXPECT_EQ(word(r, ray, "value1"), ray + 160u);
      EXPECT_EQ(word(r, ray, "value2"), 1u);
    }
    EXPECT_EQ(word(r, 0, "value3"), 28u);  // the hit: 3 x 8 + 4
    EXPECT_EQ(word(r, 1, "value3"), 9u);   // the miss
  }
}

TEST(ModelCallData, LocationsAndWordsOutsideTheirTypesAreErrors) {
  EXPECT_NE(firstErrorAfter(kCallDataTypes, "{index: 1, location: 2, word1: 8}",
                            "{index: 1, location: 3, word1: 8}")
                .find("pipeline.hit_groups[0].closest_hit[0].call.location: callable data "
                      "location 3, but pipeline.callable_data declares 3"),
            std::string::npos);
  EXPECT_NE(firstErrorAfter(kCallDataTypes, "location: 2, word1: call.word5",
                            "location: 2, word2: call.word5")
                .find("word 2, but location 2's callable data type has 2 word(s)"),
            std::string::npos);
  EXPECT_NE(firstErrorAfter(kCallDataTypes, "{word1: {mul: [call.word1, 3]}",
                            "{word1: {mul: [call.word4, 3]}")
                .find("pipeline.callables[1]"),
            std::string::npos);
  EXPECT_NE(firstErrorAfter(kCallDataTypes, "{call_data: 2, program", "{call_data: 5, program")
                .find("pipeline.callables[1].call_data: callable data location 5, but "
                      "pipeline.callable_data declares 3"),
            std::string::npos);
  EXPECT_NE(firstErrorAfter(kCallDataTypes, "[{}, {words: 6}, {words: 2}]", "[{}, {words: 53}]")
                .find("pipeline.callable_data[1].words"),
            std::string::npos);
  EXPECT_NE(firstErrorAfter(kCallDataTypes, "value: callee.word0,", "value: callee.word6,")
                .find("callee.word6: word 6, but the largest callable data type has 6"),
            std::string::npos);
}

TEST(ModelCallData, ACallableOfAnotherTypeMakesTheRayUndefined) {
  std::string text = kCallDataTypes;
  // Raygen passes location 2 (two words) to callable 0, which takes location 1's.
  const std::string call = "location: 1, word0: {add: [launch_id_x, 10]}, word5: 50";
  text.replace(text.find(call), call.size(), "location: 2, word0: 7, word1: 5");
  const Case c = parseInline(text);
  for (ModelTier tier : kTiers) {
    const Results r = runTier(c, tier);
    SCOPED_TRACE(modelTierName(tier));
    ASSERT_EQ(r.undefined.size(), 2u);
    for (const UndefinedRay& u : r.undefined) {
      EXPECT_EQ(u.reason, UndefinedReason::CallDataType);
      EXPECT_NE(u.what.find("pipeline.callables[0]: its incoming callable data has the type of "
                            "location 1 (6 words), the call passes location 2 (2 words)"),
                std::string::npos)
          << u.what;
    }
  }
}

}  // namespace
}  // namespace rayspec::model_test
