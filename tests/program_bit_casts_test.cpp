// Exactness claims (program/check_bit_casts.h): float_bits of a Float the
// device computes is refused naming its line and field; of a value the case
// gives (a literal, a ray parameter as passed, bits it built) it is accepted.
#include <gtest/gtest.h>

#include <string>

#include "parse_support.h"

namespace rayspec {
namespace {

// One triangle, one ray; closest-hit's statements `chit` (line 11 on) and
// the miss's `miss`, both recording `value`.
std::string bitsCase(const std::string& chit, const std::string& miss = "[record: {value: 0}]") {
  return "rules: [R-PREC]\n"
         "scene:\n"
         "  blas:\n"
         "    t: [{triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}}]\n"
         "  instances: [{blas: t}]\n"
         "rays:\n"
         "  list: [{origin: [0.2, 0.2, 1], direction: [0, 0, -1]}]\n"
         "pipeline:\n"
         "  miss: [" +
         miss +
         "]\n"
         "  hit_groups:\n"
         "    - closest_hit:\n" +
         chit +
         "outputs:\n"
         "  per_ray: [value]\n";
}

TEST(BitCasts, TheBitsOfAHitsTAreRefused) {
  expectError(parse(bitsCase("        - record: {value: {float_bits: hit_t}}\n")), 12,
              "closest_hit[0].record.value", "not portable");
}

// Through a local, set from the t after a literal: flow-insensitive.
TEST(BitCasts, ALocalThatHoldsAComputedValueIsComputed) {
  expectError(parse(bitsCase("        - let: {t: 1.5}\n"
                             "        - set: {t: {mul: [hit_t, 2.0]}}\n"
                             "        - record: {value: {float_bits: var.t}}\n")),
              14, "closest_hit[2].record.value", "not portable");
}

// Arithmetic on given values may be fused or rounded otherwise: refused too.
TEST(BitCasts, ArithmeticOnGivenValuesIsComputed) {
  expectError(parse(bitsCase("        - record: {value: {float_bits: {add: [ray_tmin, 1.0]}}}\n")),
              12, "record.value", "not portable");
}

TEST(BitCasts, ValuesTheCaseGivesAreAccepted) {
  const ParseResult r =
      parse(bitsCase("        - let: {k: {bits_float: 0x3FC00000}}\n"
                     "        - record: {value: {bit_xor: [{float_bits: var.k}, "
                     "{float_bits: {max: [ray_tmin, {x: world_ray_origin}]}}]}}\n",
                     "[record: {value: {float_bits: ray_tmax}}]"));
  EXPECT_TRUE(r.value.has_value()) << allErrors(r);
}

// In closest-hit tmax is the hit's t, not the trace's own.
TEST(BitCasts, TmaxOutsideMissIsTheHitsT) {
  expectError(parse(bitsCase("        - record: {value: {float_bits: ray_tmax}}\n")), 12,
              "record.value", "not portable");
}

}  // namespace
}  // namespace rayspec
