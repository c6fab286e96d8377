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

// Words indexed by a value (payload_word .. callee_word, store: payload.words
// and call.words), each index modulo the words of its array's type: the
// incoming payload's own type (4 words at location 1), a child's and a
// callee's the largest type's (4; 3), the incoming callable data's its own (3).
const std::string kIndexedWords = std::string("rules: [R-PAYLOAD]\n") + kTriangleHitAndMiss +
                                  R"(pipeline:
  max_recursion: 2
  payloads: [{}, {words: 4}, {words: 2}]
  callable_data: [{}, {words: 3}]
  raygen:
    - trace: {location: 1, payload: {word0: 1}}
    - record: {value: payload.value, value1: {payload_word: 6}, value2: {payload_word: 7},
               value3: {payload_word: 4}}
  miss:
    - {payload: 1, program: [store: {array: payload.words, index: {add: [launch_id_x, 5]}, value: 9}]}
    - {payload: 2, program: [store: {array: payload.words, index: 3, value: 77}]}
  hit_groups:
    - payload: 1
      closest_hit:
        - repeat: 3
          var: k
          from: 1
          do:
            - store: {array: payload.words, index: var.k,
                      value: {add: [{mul: [{payload_word: {sub: [var.k, 1]}}, 10]}, var.k]}}
        - trace: {location: 2, miss: 1, origin: [0.0, 0.0, 1.0], direction: [0.0, 0.0, 1.0]}
        - store: {array: payload.words, index: 4, value: {add: [{child_word: 5}, {child_word: 2}]}}
        - call: {index: 0, location: 1, word0: {payload_word: 2}}
        - payload: {value: {callee_word: 4}}
  callables:
    - {call_data: 1, program: [store: {array: call.words, index: 4, value: {add: [{call_word: 3}, 1]}}]}
outputs:
  per_ray: [value, value1, value2, value3]
)";

TEST(ModelPayload, WordsIndexedByAValueWrapAtTheirTypesWords) {
  const Case c = parseInline(kIndexedWords);
  for (ModelTier tier : kTiers) {
    const Results r = runTier(c, tier);
    SCOPED_TRACE(modelTierName(tier));
    // Hit: words 1, 11, 112, 1123; the nested miss writes word 3 % 2 = 1 of
    // its two (77), child word 5 % 4 = 1 is 77 and child word 2 lies beyond
    // that type (0): word 4 % 4 = 0 becomes 77. The callable gets word 0 =
    // 112 and writes word 4 % 3 = 1 = call word 3 % 3 = 0, plus 1.
    EXPECT_EQ(word(r, 0, "value"), 113u);
    EXPECT_EQ(word(r, 0, "value1"), 112u);  // word 6 % 4 = 2
    EXPECT_EQ(word(r, 0, "value2"), 1123u);
    EXPECT_EQ(word(r, 0, "value3"), 77u);
    // Miss (launch id 1): word (1 + 5) % 4 = 2 is 9; word 0 as it started.
    EXPECT_EQ(word(r, 1, "value"), 0u);
    EXPECT_EQ(word(r, 1, "value1"), 9u);
    EXPECT_EQ(word(r, 1, "value2"), 0u);
    EXPECT_EQ(word(r, 1, "value3"), 1u);
  }
}

TEST(ModelPayload, AnIndexedWordNeedsATypeWithWordsAndAStageThatHoldsIt) {
  std::string none = kIndexedWords;
  none.replace(none.find("{}, {words: 4}, {words: 2}"), 26, "{}, {}, {}");
  const ParseResult p = parseCaseText(none, "indexed.yaml", "indexed");
  ASSERT_FALSE(p.value);
  EXPECT_NE(p.errors.front().format().find("indexes words, but"), std::string::npos)
      << p.errors.front().format();
  std::string raygen = kIndexedWords;
  raygen.replace(raygen.find("    - record: {value: payload.value,"), 0,
                 "    - store: {array: payload.words, index: 0, value: 1}\n");
  const ParseResult q = parseCaseText(raygen, "indexed.yaml", "indexed");
  ASSERT_FALSE(q.value);
  EXPECT_NE(q.errors.front().format().find("payload.words is not writable in raygen"),
            std::string::npos)
      << q.errors.front().format();
}

}  // namespace
}  // namespace rayspec::model_test
