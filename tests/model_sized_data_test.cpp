// Sized members of the pipeline interface (pipeline.payloads[].sized,
// callable_data[].sized, hit_attribute.sized): what the caller or reporter
// writes reaches the stages it calls, what they write comes back, typed
// (wrapping integers, exact floats), in every tier; a member its type does
// not declare, an unknown type, and a hit attribute over 32 bytes are errors
// at the case line; the planted faults halve each member's bits.
#include "model_support.h"

namespace rayspec::model_test {
namespace {

// Ray 0 hits the triangle, ray 1 misses. Raygen starts the payload's int8 at
// -5; closest-hit adds 100 to it (95) and writes the float64 2^40 + 3 and
// the u16vec3 (1, 65535, 7); miss writes -128 and 2^40 + 1. A nested trace
// from closest-hit comes back through child.*; raygen's call starts the int8
// at 120, the callable adds 10 (wrapping to -126) and writes an f16vec2.
const std::string kSizedData = std::string("rules: [R-PAYLOAD]\n") + kTriangleHitAndMiss +
                               R"(pipeline:
  max_recursion: 2
  payloads: [{sized: [int8, float64, u16vec3]}]
  callable_data: [{words: 1, sized: [int8, f16vec2]}]
  raygen:
    - trace: {payload: {int8: {sub: [{int8: 0}, {int8: 5}]}}}
    - record: {value: {uint: payload.int8},
               value1: {uint: {sub: [payload.float64, 1099511627776.0]}},
               value2: {uint: {y: payload.u16vec3}}}
    - call: {index: 0, int8: {int8: 120}, word0: 4}
    - record: {value3: {uint: callee.int8}, value4: {float_bits: {float: {y: callee.f16vec2}}}}
  miss:
    - [payload: {int8: {int8: 128}, float64: {add: [1099511627776.0, {float64: 1}]}}]
  hit_groups:
    - closest_hit:
        - payload: {int8: {add: [payload.int8, {int8: 100}]},
                    float64: {add: [1099511627776.0, {float64: 3}]},
                    u16vec3: {u16vec3: [{uint16: 1}, {uint16: 65535}, {uint16: 7}]}}
        - trace: {origin: [0.0, 0.0, 1.0], direction: [0.0, 0.0, 1.0]}
        - record: {value5: {uint: child.int8}}
  callables:
    - - call_data: {int8: {add: [call.int8, {int8: 10}]},
                    f16vec2: {f16vec2: [{float16: 1}, {mul: [{float16: 3}, 0.5]}]}}
outputs:
  per_ray: [value, value1, value2, value3, value4, value5]
)";

TEST(ModelSizedData, SizedMembersTravelTypedThroughTracesAndCalls) {
  const Case c = parseInline(kSizedData);
  ASSERT_EQ(c.pipeline.payload_sized[0],
            (SizedMembers{ValueType::Int8, ValueType::Float64, ValueType::Uint16Vec3}));
  ASSERT_EQ(c.pipeline.call_data_sized[0], (SizedMembers{ValueType::Int8, ValueType::Float16Vec2}));
  for (ModelTier tier : kTiers) {
    const Results r = runTier(c, tier);
    SCOPED_TRACE(modelTierName(tier));
    ASSERT_TRUE(r.undefined.empty()) << r.undefined[0].what;
    EXPECT_EQ(word(r, 0, "value"), 95u);
    EXPECT_EQ(word(r, 0, "value1"), 3u);
    EXPECT_EQ(word(r, 0, "value2"), 65535u);
    EXPECT_EQ(word(r, 0, "value5"), static_cast<uint32_t>(-128)) << "the nested miss's int8";
    EXPECT_EQ(word(r, 1, "value"), static_cast<uint32_t>(-128));
    EXPECT_EQ(word(r, 1, "value1"), 1u);
    EXPECT_EQ(word(r, 1, "value2"), 0u) << "a member the miss never writes stays zero";
    // 120 + 10 wraps to -126; 1.5 as a float's bits.
    EXPECT_EQ(word(r, 0, "value3"), static_cast<uint32_t>(-126));
    EXPECT_EQ(word(r, 0, "value4"), 0x3FC00000u);
  }
}

TEST(ModelSizedData, TheHalvingFaultsChangeWhatComesBack) {
  const Case c = parseInline(kSizedData);
  ModelOptions o{ModelTier::Fast, 1};
  o.faults.sized_payload_halved = true;
  o.faults.sized_call_data_halved = true;
  const Results r = runOnModel(c, derivePlan(c), o);
  // 95 = 0x5F keeps 0x50; -126 = 0x82 keeps 0x80 (-128); 2^40 + 3 loses its 3.
  EXPECT_EQ(word(r, 0, "value"), 0x50u);
  EXPECT_EQ(word(r, 0, "value1"), 0u);
  EXPECT_EQ(word(r, 0, "value3"), static_cast<uint32_t>(-128));
}

TEST(ModelSizedData, MembersOutsideTheirTypesAndUnknownTypesAreErrors) {
  EXPECT_EQ(firstErrorAfter(kSizedData, "[{sized: [int8, float64, u16vec3]}]",
                            "[{sized: [int8, float64, u16vec5]}]"),
            "pipeline.payloads[0].sized[2]: unknown sized type 'u16vec5' (int8 .. float64, "
            "i8vec2 .. f64vec4)");
  EXPECT_EQ(firstErrorAfter(kSizedData, "[{sized: [int8, float64, u16vec3]}]",
                            "[{sized: [int8, float64, int8]}]"),
            "pipeline.payloads[0].sized[2]: sized type 'int8' listed twice (one member per type)");
  EXPECT_NE(firstErrorAfter(kSizedData, "value5: {uint: child.int8}", "value5: {uint: child.int16}")
                .find("child.int16: the largest payload type has no int16 member "
                      "(pipeline.payloads[].sized)"),
            std::string::npos);
  EXPECT_NE(firstErrorAfter(kSizedData, "int8: {int8: 120}", "uint8: {uint8: 120}")
                .find("call.uint8: location 0's callable data type has no uint8 member"),
            std::string::npos);
  EXPECT_NE(firstErrorAfter(kSizedData, "f16vec2: [{float16: 1},", "f16vec2: [{x: call.f16vec3},")
                .find("call.f16vec3: this callable's data type has no f16vec3 member"),
            std::string::npos);
  // A member is written with a value of its own type.
  EXPECT_NE(firstErrorAfter(kSizedData, "- trace: {payload: {int8: {sub: [{int8: 0}, {int8: 5}]}}}",
                            "- trace: {payload: {int8: 2.5}}")
                .find("int8"),
            std::string::npos);
}

// A box under ray 0 whose intersection shader reports sized members, read by
// any-hit and closest-hit.
const std::string kSizedAttribute = std::string("rules: [R-PAYLOAD]\n") + R"(scene:
  blas:
    b: [{aabbs: [[-1, -1, -1, 1, 1, 1]]}]
  instances: [{blas: b}]
rays:
  list: [{origin: [0, 0, 5], direction: [0, 0, -1]}]
pipeline:
  hit_attribute: {words: 1, sized: [int16, float64]}
  hit_groups:
    - intersection:
        - report: {t: 4.0, kind: 1, word0: 9, int16: {sub: [{int16: 0}, {int16: 300}]},
                   float64: {add: [1099511627776.0, {float64: 1}]}}
      any_hit:
        - record: {value1: {uint: attribute.int16}}
      closest_hit:
        - record: {value: {uint: {sub: [attribute.float64, 1099511627776.0]}},
                   value2: attribute.word0}
outputs:
  per_ray: [value, value1, value2]
)";

TEST(ModelSizedData, AReportsSizedMembersReachAnyHitAndClosestHit) {
  const Case c = parseInline(kSizedAttribute);
  // The vec2, a word at 8, int16 at 16, float64 at 24: each member aligned
  // to 8, the largest scalar alignment of any (Vulkan's rule for a block
  // with no explicit offsets).
  ASSERT_EQ(c.pipeline.attributeBytes(), 32u);
  for (ModelTier tier : kTiers) {
    const Results r = runTier(c, tier);
    SCOPED_TRACE(modelTierName(tier));
    EXPECT_EQ(word(r, 0, "value"), 1u);
    EXPECT_EQ(word(r, 0, "value1"), static_cast<uint32_t>(-300));
    EXPECT_EQ(word(r, 0, "value2"), 9u);
  }
  ModelOptions o{ModelTier::Fast, 1};
  o.faults.sized_attribute_halved = true;
  const Results r = runOnModel(c, derivePlan(c), o);
  EXPECT_EQ(word(r, 0, "value"), 0u) << "2^40 + 1 keeps its upper 32 bits: 2^40";
}

TEST(ModelSizedData, AHitAttributeOverThirtyTwoBytesIsAnError) {
  EXPECT_EQ(firstErrorAfter(kSizedAttribute, "sized: [int16, float64]", "sized: [f64vec4]"),
            "pipeline.hit_attribute.sized: the hit attribute holds 48 bytes (its vec2, 1 word(s) "
            "and these members, each aligned to the largest scalar of any), over the 32 every "
            "device allows (maxRayHitAttributeSize)");
  // 28 bytes packed by each member's own alignment, 40 by the largest one's.
  EXPECT_NE(firstErrorAfter(kSizedAttribute, "sized: [int16, float64]", "sized: [int16, f64vec2]")
                .find("holds 40 bytes"),
            std::string::npos);
  EXPECT_EQ(hitAttributeBytes(0, {ValueType::Int16, ValueType::Int16Vec2, ValueType::Int16Vec3,
                                  ValueType::Int16Vec4}),
            32u)
      << "aligned to 4 (the vec2's floats): 8, 12, 16, 24";
  EXPECT_EQ(hitAttributeBytes(0, {ValueType::Float64Vec3}), 32u);
  EXPECT_NE(firstErrorAfter(kSizedAttribute, "value1: {uint: attribute.int16}",
                            "value1: {uint: attribute.int8}")
                .find("attribute.int8: the hit attribute has no int8 member"),
            std::string::npos);
  EXPECT_NE(firstErrorAfter(kSizedAttribute, "int16: {sub: [{int16: 0}, {int16: 300}]}",
                            "uint16: {uint16: 300}")
                .find("report uint16: the hit attribute has no uint16 member"),
            std::string::npos);
}

}  // namespace
}  // namespace rayspec::model_test
