// The payload a trace starts with (`trace: {payload: ...}`): what the caller
// writes reaches the stages of that trace, and what they write comes back
// (R-PAYLOAD), in raygen and in a nested trace, in every tier. Payload types
// by location (pipeline.payloads): their words travel the same way, a word
// beyond a type is an error at the case line, and a shader of another type
// than the trace's makes that ray undefined (R-UB).
#include "model_support.h"

namespace rayspec::model_test {
namespace {

// Ray 0 hits the triangle, ray 1 misses. Raygen traces twice: the second
// trace starts from the first one's result plus 5. Closest-hit adds 100 and
// traces again (nested, toward nothing) starting from its own payload times
// 2, and keeps the miss's answer (+1000) in value1.
const std::string kStartPayload = std::string("rules: [R-PAYLOAD]\n") + kTriangleHitAndMiss +
                                  R"(pipeline:
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

// The case file cases/recursion/payload-types.yaml, as its description works out.
const std::string kPayloadTypes = std::string("rules: [R-PAYLOAD]\n") + kTriangleHitAndMiss +
                                  R"(pipeline:
  max_recursion: 2
  payloads: [{}, {words: 10}, {words: 2}]
  raygen:
    - trace: {location: 1, payload: {value: 5, word5: 50, word9: 90}}
    - record: {value: payload.value, value1: payload.word0, value2: payload.word9,
               value3: payload.word5}
  miss:
    - {payload: 1, program: [payload: {word9: {add: [payload.word9, 1]}}]}
    - {payload: 2, program: [payload: {word1: {add: [payload.word0, 7]}}]}
  hit_groups:
    - payload: 1
      any_hit: [payload: {word0: {add: [primitive_id, 11]}}]
      closest_hit:
        - payload: {word9: {add: [payload.word9, payload.word0]}}
        - trace: {location: 2, miss: 1, origin: [0.0, 0.0, 1.0], direction: [0.0, 0.0, 1.0],
                  payload: {word0: payload.word5}}
        - payload: {word5: child.word1, value: {add: [child.word0, child.value]}}
outputs:
  per_ray: [value, value1, value2, value3]
)";

TEST(ModelPayload, PayloadWordsTravelWithTheTypeOfTheirLocation) {
  const Case c = parseInline(kPayloadTypes);
  ASSERT_EQ(c.pipeline.payload_words, (std::vector<uint32_t>{0, 10, 2}));
  ASSERT_EQ(c.pipeline.miss_payload, (std::vector<uint32_t>{1, 2}));
  ASSERT_EQ(c.pipeline.hit_groups[0].payload, 1u);
  for (ModelTier tier : kTiers) {
    const Results r = runTier(c, tier);
    SCOPED_TRACE(modelTierName(tier));
    ASSERT_TRUE(r.undefined.empty()) << r.undefined[0].what;
    // Hit: any-hit word 0 = 11; closest-hit word 9 = 90 + 11; the nested
    // trace starts word 0 at 50, its miss sets word 1 = 57; back in value
    // (50 + 0) and word 5 (57).
    EXPECT_EQ(word(r, 0, "value"), 50u);
    EXPECT_EQ(word(r, 0, "value1"), 11u);
    EXPECT_EQ(word(r, 0, "value2"), 101u);
    EXPECT_EQ(word(r, 0, "value3"), 57u);
    // Miss: word 9 + 1, the rest as raygen started them.
    EXPECT_EQ(word(r, 1, "value"), 5u);
    EXPECT_EQ(word(r, 1, "value1"), 0u);
    EXPECT_EQ(word(r, 1, "value2"), 91u);
    EXPECT_EQ(word(r, 1, "value3"), 50u);
  }
}

TEST(ModelPayload, PayloadLocationsAndWordsOutsideTheirTypesAreErrors) {
  EXPECT_NE(firstErrorAfter(kPayloadTypes, "location: 2,", "location: 3,")
                .find("pipeline.hit_groups[0].closest_hit[1].trace.location: payload location 3, "
                      "but pipeline.payloads declares 3"),
            std::string::npos);
  EXPECT_NE(firstErrorAfter(kPayloadTypes, "payload: {word0: payload.word5}",
                            "payload: {word2: payload.word5}")
                .find("word 2, but location 2's payload type has 2 word(s)"),
            std::string::npos);
  EXPECT_NE(firstErrorAfter(kPayloadTypes, "{word1: {add: [payload.word0, 7]}}",
                            "{word1: {add: [payload.word3, 7]}}")
                .find("pipeline.miss[1]"),
            std::string::npos);
  EXPECT_NE(firstErrorAfter(kPayloadTypes, "{payload: 2, program", "{payload: 4, program")
                .find("pipeline.miss[1].payload: payload location 4, but pipeline.payloads "
                      "declares 3"),
            std::string::npos);
  EXPECT_NE(firstErrorAfter(kPayloadTypes, "[{}, {words: 10}, {words: 2}]", "[{}, {words: 59}]")
                .find("pipeline.payloads[1].words"),
            std::string::npos);
  EXPECT_NE(firstErrorAfter(kPayloadTypes, "record: {value: payload.value,",
                            "record: {value: payload.word10,")
                .find("payload.word10"),
            std::string::npos);
}

TEST(ModelPayload, AShaderOfAnotherPayloadTypeMakesTheRayUndefined) {
  std::string text = kPayloadTypes;
  // The launch trace passes location 2 (two words): the hit group and the
  // first miss shader take location 1's type (ten); the nested trace stays right.
  text.replace(text.find("location: 1, payload"), 11, "location: 2");
  text.replace(text.find("word5: 50, word9: 90"), 20, "word1: 50");
  const Case c = parseInline(text);
  for (ModelTier tier : kTiers) {
    const Results r = runTier(c, tier);
    SCOPED_TRACE(modelTierName(tier));
    ASSERT_EQ(r.undefined.size(), 2u);
    for (const UndefinedRay& u : r.undefined) {
      EXPECT_EQ(u.reason, UndefinedReason::PayloadType);
      EXPECT_NE(u.what.find("the trace passes location 2 (2 words)"), std::string::npos) << u.what;
    }
    EXPECT_NE(r.undefined[0].what.find("pipeline.hit_groups[0].any_hit"), std::string::npos)
        << r.undefined[0].what;
    EXPECT_NE(r.undefined[1].what.find("pipeline.miss[0]"), std::string::npos)
        << r.undefined[1].what;
  }
}

}  // namespace
}  // namespace rayspec::model_test
