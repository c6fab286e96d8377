// The model's meaning of locals, arrays, repeat, break, continue, switch,
// functions and return (program/program.h), ray by ray.
#include "model_support.h"

namespace rayspec::model_test {
namespace {

// Four rays along x (launch_id_x 0..3) that all miss; `raygen` is the raygen
// program (YAML, indented by four), `extra` more pipeline fields, `miss` the
// miss shader's program.
Case missCase(const std::string& raygen, const std::string& extra = "",
              const std::string& miss = "[payload: {value: 5}]") {
  return parseInline(
      "rules: [R-CONTROL-FLOW]\n"
      "scene:\n"
      "  blas:\n"
      "    t: [{triangles: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}}]\n"
      "  instances: [{blas: t}]\n"
      "rays:\n"
      "  grid: {size: [4, 1], origin: [10, 10, 1], du: [1, 0, 0], dv: [0, 1, 0], "
      "direction: [0, 0, -1]}\n"
      "pipeline:\n" +
      extra + "  miss: [" + miss +
      "]\n"
      "  hit_groups: [{closest_hit: [payload: {value: 6}]}]\n"
      "  raygen:\n" +
      raygen +
      "outputs:\n"
      "  per_ray: [value, value1, value2]\n");
}

std::vector<uint32_t> values(const Results& r, const char* field) {
  std::vector<uint32_t> v;
  for (uint32_t i = 0; i < 4; ++i) v.push_back(word(r, i, field));
  return v;
}

using V = std::vector<uint32_t>;

TEST(ModelControlFlow, RepeatRunsItsCountWithBreakAndContinue) {
  // sum of k for k in 2 .. 2 + x, skipping 3, stopping at 5.
  Case c = missCase(
      "    - let: {sum: 0, trips: 0}\n"
      "    - repeat: {add: [launch_id_x, 1]}\n"
      "      var: k\n"
      "      from: 2\n"
      "      do:\n"
      "        - set: {trips: {add: [var.trips, 1]}}\n"
      "        - if: {eq: [var.k, 3]}\n"
      "          then: [continue]\n"
      "        - if: {eq: [var.k, 5]}\n"
      "          then: [break]\n"
      "        - set: {sum: {add: [var.sum, var.k]}}\n"
      "    - record: {value: var.sum, value1: var.trips}\n");
  const Results r = runTier(c, ModelTier::Fast);
  EXPECT_EQ(values(r, "value"), (V{2, 2, 6, 6}));
  EXPECT_EQ(values(r, "value1"), (V{1, 2, 3, 4}));
}

TEST(ModelControlFlow, RepeatCountIsClamped) {
  Case c = missCase(
      "    - let: {n: 0}\n"
      "    - repeat: {add: [4294967295, launch_id_x]}\n"
      "      do: [{set: {n: {add: [var.n, 1]}}}]\n"
      "    - record: {value: var.n}\n");
  const Results r = runTier(c, ModelTier::Fast);
  // 0xFFFFFFFF + x wraps to x - 1 for x > 0.
  EXPECT_EQ(values(r, "value"), (V{kMaxLoopTrips, 0, 1, 2}));
}

TEST(ModelControlFlow, SwitchTakesOneCaseOrTheDefault) {
  Case c = missCase(
      "    - let: {v: 0}\n"
      "    - switch: launch_id_x\n"
      "      cases:\n"
      "        1: [{set: {v: 10}}]\n"
      "        3: [{set: {v: 30}}]\n"
      "      default: [{set: {v: 99}}]\n"
      "    - record: {value: var.v}\n");
  EXPECT_EQ(values(runTier(c, ModelTier::Fast), "value"), (V{99, 10, 99, 30}));
}

TEST(ModelControlFlow, ArraysIndexModuloTheirSize) {
  Case c = missCase(
      "    - array: {name: a, of: uint, size: 3}\n"
      "    - repeat: 5\n"
      "      var: i\n"
      "      do: [{store: {array: a, index: var.i, value: {add: [var.i, 10]}}}]\n"
      "    - record: {value: {load: [var.a, launch_id_x]}}\n");
  // Stores 3 and 4 overwrite elements 0 and 1.
  EXPECT_EQ(values(runTier(c, ModelTier::Fast), "value"), (V{13, 14, 12, 13}));
}

TEST(ModelControlFlow, FunctionsHaveTheirOwnFrameAndReturn) {
  Case c = missCase(
      "    - let: {a: 7}\n"
      "    - invoke: f\n"
      "      with: {a: launch_id_x, b: 100}\n"
      "    - record: {value: var.a}\n",
      "  functions:\n"
      "    f:\n"
      "      params: {a: uint, b: uint}\n"
      "      do:\n"
      "        - set: {a: {add: [var.a, var.b]}}\n"
      "        - record: {value1: var.a}\n"
      "        - if: {odd: var.a}\n"
      "          then: [return]\n"
      "        - record: {value2: 1}\n");
  const Results r = runTier(c, ModelTier::Fast);
  EXPECT_EQ(values(r, "value"), (V{7, 7, 7, 7}));  // the caller's a is its own
  EXPECT_EQ(values(r, "value1"), (V{100, 101, 102, 103}));
  EXPECT_EQ(values(r, "value2"), (V{1, 0, 1, 0}));
}

TEST(ModelControlFlow, LocalsLiveAcrossATrace) {
  Case c = missCase(
      "    - let: {before: {mul: [launch_id_x, 3]}}\n"
      "    - trace: {}\n"
      "    - record: {value: var.before, value1: payload.value}\n");
  const Results r = runTier(c, ModelTier::Fast);
  EXPECT_EQ(values(r, "value"), (V{0, 3, 6, 9}));
  EXPECT_EQ(values(r, "value1"), (V{5, 5, 5, 5}));
  ModelOptions o{ModelTier::Fast, 1};
  o.faults.locals_lost_across_calls = true;
  const Results lost = runOnModel(c, derivePlan(c), o);
  EXPECT_EQ(values(lost, "value"), (V{0, 0, 0, 0}));
}

TEST(ModelControlFlow, EachShaderReadsItsOwnSpecialization) {
  const Case c = missCase(
      "    - trace: {}\n"
      "    - record: {value: const.n, value1: payload.value}\n",
      "  constants: {n: 2}\n"
      "  specialize: {raygen: {n: 40}}\n",
      "[payload: {value: const.n}]");
  const Results r = runTier(c, ModelTier::Fast);
  EXPECT_EQ(values(r, "value"), (V{40, 40, 40, 40}));  // raygen's own value
  EXPECT_EQ(values(r, "value1"), (V{2, 2, 2, 2}));     // the miss keeps the default
}

}  // namespace
}  // namespace rayspec::model_test
