// The fault matrix of generated cases (mutate/fault_matrix.h): a fault that
// breaks what a case shows is found, by the first case that shows it; one
// the case gives nothing to break is not, and is listed as never found with
// why; legal variations and process faults are not in it.
#include <gtest/gtest.h>

#include "fault/planted_fault.h"
#include "model_support.h"
#include "mutate/fault_matrix.h"
#include "mutate/legal_devices.h"

namespace rayspec {
namespace {

using model_test::diagonalSquareBlas;
using model_test::parseInline;

// One opaque triangle: ray 0 hits it, ray 1 misses everything. No mask, no
// box, no any-hit: the faults of those have nothing to change.
const char* kCase = R"(rules: [R-BUILTIN]
scene:
  blas:
    tri:
      - triangles:
          vertices: [[-1, -1, 0], [1, -1, 0], [0, 1, 0]]
        flags: [opaque]
  instances: [{blas: tri, custom_index: 5}]
rays:
  list:
    - {origin: [0, -0.25, 5], direction: [0, 0, -1]}
    - {origin: [7, 7, 5], direction: [0, 0, -1]}
  tmin: 0.001
  tmax: 100
pipeline:
  miss:
    - [count: miss, record: {hit: 0}]
  hit_groups:
    - closest_hit: [count: chit, record: [hit, primitive_id, instance_custom_index, hit_t]]
outputs:
  counters: [miss, chit]
  per_ray: [hit, primitive_id, instance_custom_index, hit_t]
)";

SavedCase savedOf(const std::string& text) {
  const Case c = parseInline(text);
  const Plan plan = derivePlan(c);
  Results model = runOnModel(c, plan, ModelOptions{ModelTier::Exact, 1});
  Results device = perfectDevice(c, model);
  device.backend = "vulkan";
  return {c, plan, device, model};
}

// Two triangles share the diagonal x = y of a square; ray 0 meets it exactly
// (two legal answers), ray 1 hits clearly. The instance's mask 3 meets every
// ray's cull mask (0xFF), so ignoring masks changes nothing.
const std::string kMaskedEdgeCase = R"(rules: [R-WATERTIGHT]
scene:
  blas:
)" + diagonalSquareBlas("[opaque]") +
                                    R"(  instances: [{blas: square, mask: 3}]
rays:
  list:
    - {origin: [0.25, 0.25, 5], direction: [0, 0, -1]}
    - {origin: [0.5, -0.5, 5], direction: [0, 0, -1]}
  tmin: 0.001
  tmax: 100
pipeline:
  miss:
    - [count: miss, record: {hit: 0}]
  hit_groups:
    - closest_hit: [count: chit, record: [hit, primitive_id]]
outputs:
  counters: [miss, chit]
  per_ray: [hit, primitive_id]
)";

const FaultRow& row(const FaultMatrix& m, const std::string& fault) {
  for (const FaultRow& r : m.rows())
    if (r.fault == fault) return r;
  ADD_FAILURE() << fault << " is not in the matrix";
  return m.rows().front();
}

TEST(FaultMatrix, RuleBreakingFaultsOnly) {
  const FaultMatrix m;  // every rule-breaking fault
  EXPECT_GE(m.rows().size(), 80u);
  for (const FaultRow& r : m.rows()) {
    EXPECT_FALSE(isProcessFault(r.fault)) << r.fault;
    EXPECT_NE(findFault(r.fault)->breaks.rfind("legal:", 0), 0u) << r.fault;
  }
  EXPECT_EQ(row(m, "drop-miss").rules.find("R-MISS"), 0u) << row(m, "drop-miss").rules;
}

TEST(FaultMatrix, FoundByTheFirstCaseThatShowsIt) {
  const SavedCase saved = savedOf(kCase);
  FaultMatrix m;
  m.add("fuzz/seed-1", saved);
  m.add("fuzz/seed-2", saved);
  EXPECT_EQ(m.cases(), 2u);
  for (const char* fault : {"drop-miss", "shift-t", "builtin-wrong"}) {
    const FaultRow& r = row(m, fault);
    EXPECT_EQ(r.found_by, "fuzz/seed-1") << fault << ": " << r.what;
    EXPECT_EQ(r.tried, 1u) << fault;  // not planted again once found
    EXPECT_EQ(r.status, "Fail") << fault;
  }
  // No mask, no box, no any-hit: nothing to break, never found.
  for (const char* fault : {"instance-mask-ignored", "duplicate-any-hit"}) {
    const FaultRow& r = row(m, fault);
    EXPECT_TRUE(r.found_by.empty()) << fault << ": " << r.headline;
    EXPECT_EQ(r.tried, 2u) << fault;
    EXPECT_EQ(r.applied, 0u) << fault;
  }
  EXPECT_GT(m.found(), 3u);
  EXPECT_LT(m.found(), m.rows().size());
  const std::string text = m.text();
  EXPECT_EQ(text.rfind("Fault matrix: " + std::to_string(m.found()) + " of " +
                           std::to_string(m.rows().size()),
                       0),
            0u)
      << text;
  EXPECT_NE(text.find("- instance-mask-ignored ("), std::string::npos) << text;
  EXPECT_EQ(text.find("- drop-miss ("), std::string::npos) << text;
}

// A device that took the other legal answer of an ambiguous ray is not
// "changed" by a case mutation that changes nothing the model sees: the
// mutated case's answers are compared with the model's own device on the
// case, not with the saved device (which made every mutation look applied).
TEST(FaultMatrix, ACaseMutationChangesNothingWhereTheModelSeesNoDifference) {
  SavedCase saved = savedOf(kMaskedEdgeCase);
  bool other_answer = false;
  for (LegalVariant& v : legalVariants(saved.c, saved.plan, saved.model, 1))
    if (v.name == "answer-1" && v.applied) {
      saved.device = v.device;
      other_answer = true;
    }
  ASSERT_TRUE(other_answer) << "the edge ray has a second legal answer";
  saved.device.backend = "vulkan";
  FaultMatrix m;
  m.add("fuzz/seed-1", saved);
  const FaultRow& mask = row(m, "instance-mask-ignored");
  EXPECT_EQ(mask.applied, 0u) << mask.what;
  EXPECT_NE(mask.what.find("changed nothing"), std::string::npos) << mask.what;
  // A record fault still changes the saved device's records, and is found.
  EXPECT_EQ(row(m, "builtin-wrong").found_by, "fuzz/seed-1") << row(m, "builtin-wrong").what;
}

}  // namespace
}  // namespace rayspec
