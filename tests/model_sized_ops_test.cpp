// The model's meaning of the sized scalars and vectors (model/sized_ops.cpp):
// integers wrap modulo 2^bits, conversions as GLSL's constructors, float16
// and float64 exact or a case error, vectors lane by lane, and the planted
// faults that halve them or rotate a vector's lanes across a call, or start
// a sized array at one.
#include "model_support.h"

namespace rayspec::model_test {
namespace {

// Two rays (launch_id_x 0, 1) that miss; `raygen` is the raygen program
// (YAML, indented by four).
Case sizedCase(const std::string& raygen) {
  return parseInline(
      "rules: [R-LIVE-STATE]\n"
      "scene:\n"
      "  blas:\n"
      "    t: [{triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}}]\n"
      "  instances: [{blas: t}]\n"
      "rays:\n"
      "  grid: {size: [2, 1], origin: [10, 10, 1], du: [1, 0, 0], dv: [0, 1, 0], "
      "direction: [0, 0, -1]}\n"
      "pipeline:\n"
      "  miss: [[payload: {value: 5}]]\n"
      "  hit_groups: [{closest_hit: [payload: {value: 6}]}]\n"
      "  raygen:\n" +
      raygen +
      "outputs:\n"
      "  per_ray: [value, value1, value2]\n");
}

// A case whose raygen records @V@ (to replace) as value: line 12.
std::string sizedCaseTextForErrors() {
  return "rules: [R-LIVE-STATE]\n"
         "scene:\n"
         "  blas:\n"
         "    t: [{triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}}]\n"
         "  instances: [{blas: t}]\n"
         "rays:\n"
         "  grid: {size: [2, 1], origin: [10, 10, 1], du: [1, 0, 0], dv: [0, 1, 0], "
         "direction: [0, 0, -1]}\n"
         "pipeline:\n"
         "  miss: [[payload: {value: 5}]]\n"
         "  hit_groups: [{closest_hit: [payload: {value: 6}]}]\n"
         "  raygen:\n"
         "    - record: {value: @V@}\n"
         "outputs:\n"
         "  per_ray: [value]\n";
}

using Pair = std::vector<uint32_t>;
V sizedValues(const Results& r, const char* field) {
  return {word(r, 0, field), word(r, 1, field)};
}

TEST(ModelSizedOps, IntegersWrapAndConvertByTheirSignedness) {
  const Case c = sizedCase(
      "    - let: {a: {sub: [{int8: launch_id_x}, 100]}}\n"  // -100, -99
      "    - let: {b: {mul: [var.a, 3]}}\n"                  // -300 -> -44, -297 -> -41
      "    - let: {w: {mul: [{uint64: 4294967295}, {uint64: {add: [launch_id_x, 2]}}]}}\n"
      "    - record: {value: {uint: var.b}, value1: {high: var.w}, value2: {uint: var.w}}\n");
  const Results r = runTier(c, ModelTier::Fast);
  ASSERT_TRUE(r.ok()) << r.status_detail;
  EXPECT_EQ(sizedValues(r, "value"),
            (Pair{static_cast<uint32_t>(-44), static_cast<uint32_t>(-41)}));
  EXPECT_EQ(sizedValues(r, "value1"), (Pair{1, 2}));  // (2^32 - 1) * 2 = 2^33 - 2
  EXPECT_EQ(sizedValues(r, "value2"), (Pair{0xFFFFFFFEu, 0xFFFFFFFDu}));
}

// int32 (ivec2 .. ivec4) wraps modulo 2^32 and compares signed, where the
// same bits as uint would compare unsigned.
TEST(ModelSizedOps, Int32VectorsWrapAndCompareSigned) {
  const Case c = sizedCase(
      "    - let: {v: {ivec2: [{sub: [{int32: launch_id_x}, 2000000000]}, 2000000000]}}\n"
      "    - let: {w: {mul: [var.v, 3]}}\n"  // x: -6e9 -> -1705032704 (+2^32 * 2)
      "    - record: {value: {uint: {x: var.w}}, value1: {uint: {y: var.w}},\n"
      "              value2: {uint: {min: [{x: var.v}, {y: var.v}]}}}\n");
  const Results r = runTier(c, ModelTier::Fast);
  ASSERT_TRUE(r.ok()) << r.status_detail;
  EXPECT_EQ(sizedValues(r, "value"),
            (Pair{static_cast<uint32_t>(-6000000000LL), static_cast<uint32_t>(-5999999997LL)}));
  EXPECT_EQ(sizedValues(r, "value1"),
            (Pair{6000000000ULL & 0xFFFFFFFFu, 6000000000ULL & 0xFFFFFFFFu}));
  EXPECT_EQ(sizedValues(r, "value2"),
            (Pair{static_cast<uint32_t>(-2000000000), static_cast<uint32_t>(-1999999999)}));
}

// Integer literals over 32 bits (Expr::wide) are exact in int64 and uint64
// places, beyond the 2^53 a double holds.
TEST(ModelSizedOps, WideLiteralsAreExactIn64BitPlaces) {
  const Case c = sizedCase(
      "    - let: {u: {add: [{uint64: launch_id_x}, 18446744073709551615]}}\n"
      "    - let: {i: {add: [{int64: launch_id_x}, 0x7FFFFFFFFFFFFFFD]}}\n"
      "    - record: {value: {high: var.u}, value1: {uint: var.u}, value2: {uint: var.i}}\n");
  const Results r = runTier(c, ModelTier::Fast);
  ASSERT_TRUE(r.ok()) << r.status_detail;
  EXPECT_EQ(sizedValues(r, "value"), (Pair{0xFFFFFFFFu, 0}));   // 2^64 - 1, then 0
  EXPECT_EQ(sizedValues(r, "value1"), (Pair{0xFFFFFFFFu, 0}));  // the low bits a double loses
  EXPECT_EQ(sizedValues(r, "value2"), (Pair{0xFFFFFFFDu, 0xFFFFFFFEu}));
}

// Elsewhere a literal over 32 bits is an error naming its line and field.
TEST(ModelSizedOps, AWideLiteralOutsideA64BitPlaceIsAnErrorAtItsField) {
  const std::string text = sizedCaseTextForErrors();
  EXPECT_NE(firstErrorAfter(text, "@V@", "{add: [launch_id_x, 4294967296]}")
                .find("integer literal 4294967296 does not fit in 32 bits: only an int64 or "
                      "uint64 value takes one (here Uint)"),
            std::string::npos);
  EXPECT_NE(firstErrorAfter(text, "@V@", "{uint: {add: [{int8: 1}, 4294967296]}}")
                .find("does not fit in 32 bits"),
            std::string::npos);
  EXPECT_NE(firstErrorAfter(text, "@V@", "{uint: {add: [{int64: 1}, 9223372036854775808]}}")
                .find("out of range 0..9223372036854775807"),
            std::string::npos);
  EXPECT_EQ(firstErrorAfter(text, "@V@", "{high: {add: [{uint64: 1}, 9223372036854775808]}}"),
            "(no error)");
  EXPECT_EQ(firstErrorAfter(std::string(text).replace(text.find("@V@"), 3, "1"), "  raygen:\n",
                            "  constants: {k: 4294967296}\n  raygen:\n"),
            "pipeline.constants.k: integer literal 4294967296 does not fit in 32 bits");
  const ParseResult p = parseCaseText(
      [&] {
        std::string t = text;
        t.replace(t.find("@V@"), 3, "{uint: {mul: [{float: launch_id_x}, 5000000000]}}");
        return t;
      }(),
      "model/inline.yaml", "model/inline");
  ASSERT_FALSE(p.errors.empty());
  EXPECT_EQ(p.errors[0].loc.file, "model/inline.yaml");
  EXPECT_EQ(p.errors[0].loc.line, 12);
  EXPECT_NE(p.errors[0].loc.field.find("pipeline.raygen"), std::string::npos)
      << p.errors[0].loc.field;
}

TEST(ModelSizedOps, Float64KeepsWhatFloatLoses) {
  const Case c = sizedCase(
      "    - let: {d: {add: [{mul: [{float64: {add: [launch_id_x, 1]}}, 1099511627776.0]}, 7.5]}}\n"
      "    - record: {value: {uint: {mul: [{sub: [var.d, 7.5]}, 9.0949470177292824e-13]}},\n"
      "              value1: {uint: {sub: [var.d, {mul: [{float64: {add: [launch_id_x, 1]}}, "
      "1099511627776.0]}]}}}\n");
  const Results r = runTier(c, ModelTier::Fast);
  ASSERT_TRUE(r.ok()) << r.status_detail;
  EXPECT_EQ(sizedValues(r, "value"), (Pair{1, 2}));
  EXPECT_EQ(sizedValues(r, "value1"), (Pair{7, 7}));  // 7.5 truncated
}

TEST(ModelSizedOps, AnInexactFloat16IsACaseError) {
  const Case c = sizedCase(
      "    - let: {h: {add: [{float16: 2048}, {float16: {add: [launch_id_x, 1]}}]}}\n"
      "    - record: {value: {uint: var.h}}\n");
  const Results r = runTier(c, ModelTier::Fast);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.status_detail.find("Float16 result not exact"), std::string::npos) << r.status_detail;
}

TEST(ModelSizedOps, TheHalvingFaultKeepsTheUpperHalfAcrossATrace) {
  const Case c = sizedCase(
      "    - let: {a: {int16: {add: [launch_id_x, 0x1234]}}, h: {float16: 1.8828125}}\n"
      "    - let: {w: {mul: [{mul: [{int64: 65536}, 65536]}, {int64: {add: [launch_id_x, 5]}}]}}\n"
      "    - set: {w: {add: [var.w, 9]}}\n"
      "    - trace: {}\n"
      "    - record: {value: {uint: var.a}, value1: {float_bits: {float: var.h}},\n"
      "              value2: {bit_xor: [{uint: var.w}, {high: var.w}]}}\n");
  const Results kept = runTier(c, ModelTier::Fast);
  EXPECT_EQ(sizedValues(kept, "value"), (Pair{0x1234, 0x1235}));
  EXPECT_EQ(sizedValues(kept, "value1"), (Pair{0x3FF10000u, 0x3FF10000u}));  // 1.8828125
  EXPECT_EQ(sizedValues(kept, "value2"), (Pair{9 ^ 5, 9 ^ 6}));
  ModelOptions o{ModelTier::Fast, 1};
  o.faults.sized_locals_halved = true;
  const Results halved = runOnModel(c, derivePlan(c), o);
  EXPECT_EQ(sizedValues(halved, "value"), (Pair{0x1200, 0x1200}));
  EXPECT_EQ(sizedValues(halved, "value1"),
            (Pair{0x3FE00000u, 0x3FE00000u}));  // 1.75: the low byte 0
  EXPECT_EQ(sizedValues(halved, "value2"), (Pair{5, 6}));
}

// A struct's members keep their own types, start at zero, and are locals
// the halving fault reaches like any other.
TEST(ModelSizedOps, StructMembersKeepTheirTypesAndAreHalvedLikeLocals) {
  const Case c = sizedCase(
      "    - struct: {name: s, members: {a: int16, b: vec3, c: uint, d: i8vec2}}\n"
      "    - record: {value2: {add: [{uint: var.s.a}, {add: [var.s.c, {uint: {y: var.s.d}}]}]}}\n"
      "    - set: {s.a: {int16: {add: [launch_id_x, 0x1234]}}, s.b: [1.5, 2.5, 3.5]}\n"
      "    - set: {s.c: 0x5678, s.d: {i8vec2: [{sub: [{int8: 0}, 3]}, 0x35]}}\n"
      "    - trace: {}\n"
      "    - record: {value: {bit_xor: [{uint: var.s.a}, {uint: {z: var.s.b}}]},\n"
      "              value1: {add: [var.s.c, {uint: {y: var.s.d}}]}}\n");
  const Results kept = runTier(c, ModelTier::Fast);
  ASSERT_TRUE(kept.ok()) << kept.status_detail;
  EXPECT_EQ(sizedValues(kept, "value2"), (Pair{0, 0}));
  EXPECT_EQ(sizedValues(kept, "value"), (Pair{0x1234 ^ 3, 0x1235 ^ 3}));
  EXPECT_EQ(sizedValues(kept, "value1"), (Pair{0x5678 + 0x35, 0x5678 + 0x35}));
  ModelOptions o{ModelTier::Fast, 1};
  o.faults.sized_locals_halved = true;
  const Results halved = runOnModel(c, derivePlan(c), o);
  EXPECT_EQ(sizedValues(halved, "value"), (Pair{0x1200 ^ 3, 0x1200 ^ 3}));  // vec3 kept
  EXPECT_EQ(sizedValues(halved, "value1"), (Pair{0x5678 + 0x30, 0x5678 + 0x30}));
}

// uint's vectors wrap modulo 2^32 lane by lane, a uint beside one is every
// lane's, a lane reads back as a uint; the rotating fault reaches them.
TEST(ModelSizedOps, UintVectorsWrapLaneByLane) {
  const Case c = sizedCase(
      "    - let: {v: {mul: [{uvec3: [4000000000, {add: [launch_id_x, 7]}, 5]}, 3]}}\n"
      "    - let: {w: {max: [var.v, {uvec3: 20}]}}\n"
      "    - trace: {}\n"
      "    - record: {value: {x: var.v}, value1: {y: var.w}, value2: {z: var.w}}\n");
  const Results r = runTier(c, ModelTier::Fast);
  ASSERT_TRUE(r.ok()) << r.status_detail;
  EXPECT_EQ(sizedValues(r, "value"), (Pair{3410065408u, 3410065408u}));  // 12e9 mod 2^32
  EXPECT_EQ(sizedValues(r, "value1"), (Pair{21, 24}));
  EXPECT_EQ(sizedValues(r, "value2"), (Pair{20, 20}));
  ModelOptions o{ModelTier::Fast, 1};
  o.faults.sized_vectors_rotated = true;
  const Results rotated = runOnModel(c, derivePlan(c), o);
  EXPECT_EQ(sizedValues(rotated, "value"), (Pair{21, 24}));
}

TEST(ModelSizedOps, VectorsComputeLaneByLaneAndTheirArraysStartAtZero) {
  const Case c = sizedCase(
      "    - array: {name: a, of: i8vec3, size: 2}\n"
      "    - store: {array: a, index: 0, value: {i8vec3: [{int8: launch_id_x}, 100, 120]}}\n"
      "    - let: {v: {mul: [{load: [var.a, 0]}, 3]}, h: {f16vec2: [1.5, 2.25]}}\n"
      "    - set: {h: {add: [var.h, {f16vec2: 0.5}]}}\n"
      "    - record: {value: {uint: {z: var.v}}, value1: {uint: {x: {load: [var.a, 1]}}},\n"
      "              value2: {float_bits: {float: {sub: [{y: var.h}, {x: var.h}]}}}}\n");
  const Results r = runTier(c, ModelTier::Fast);
  ASSERT_TRUE(r.ok()) << r.status_detail;
  EXPECT_EQ(sizedValues(r, "value"), (Pair{104, 104}));  // 360 wraps to 104
  EXPECT_EQ(sizedValues(r, "value1"), (Pair{0, 0}));     // the null initialiser's zero
  EXPECT_EQ(sizedValues(r, "value2"), (Pair{0x3F400000u, 0x3F400000u}));  // 0.75
}

TEST(ModelSizedOps, TheVectorFaultsRotateLanesAndTheNullFaultStartsAtOne) {
  const Case c = sizedCase(
      "    - array: {name: a, of: u16vec3, size: 2}\n"
      "    - store: {array: a, index: 0, value: {u16vec3: [{uint16: launch_id_x}, 7, 9]}}\n"
      "    - trace: {}\n"
      "    - record: {value: {uint: {x: {load: [var.a, 0]}}}, value1: {uint: {z: {load: [var.a, "
      "0]}}},\n"
      "              value2: {uint: {y: {load: [var.a, 1]}}}}\n");
  const Results kept = runTier(c, ModelTier::Fast);
  EXPECT_EQ(sizedValues(kept, "value"), (Pair{0, 1}));
  EXPECT_EQ(sizedValues(kept, "value1"), (Pair{9, 9}));
  EXPECT_EQ(sizedValues(kept, "value2"), (Pair{0, 0}));
  ModelOptions o{ModelTier::Fast, 1};
  o.faults.sized_vectors_rotated = true;
  const Results rotated = runOnModel(c, derivePlan(c), o);
  EXPECT_EQ(sizedValues(rotated, "value"), (Pair{7, 7}));   // x takes y's
  EXPECT_EQ(sizedValues(rotated, "value1"), (Pair{0, 1}));  // z takes x's
  ModelOptions n{ModelTier::Fast, 1};
  n.faults.sized_null_not_zero = true;
  const Results ones = runOnModel(c, derivePlan(c), n);
  EXPECT_EQ(sizedValues(ones, "value2"), (Pair{1, 1}));
}

}  // namespace
}  // namespace rayspec::model_test
